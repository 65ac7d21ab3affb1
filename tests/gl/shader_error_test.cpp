// Compile errors name the module file and line.
#include "gl/context.h"
#include "gl/shader_program.h"

#include <gtest/gtest.h>

namespace aurorawall::gl {
namespace {

std::string compileError(const ShaderSource& fragment)
{
    try {
        Program::graphics(fullScreenTriangleVertexShader(), fragment);
    } catch (const ShaderError& e) {
        return e.what();
    }
    return "";
}

TEST(ShaderErrors, NameSecondModuleFileAndLine)
{
    auto context = createContext(Backend::Egl);
    const ShaderSource fragment{{"GAIN 2.0"},
                                {{"shaders/first.glsl", "float first(float x)\n{\n    return GAIN * x;\n}\n"},
                                 {"shaders/second.glsl", "out vec4 color;\n"
                                                         "void main()\n"
                                                         "{\n"
                                                         "    color = vec4(first(undeclaredThing));\n"
                                                         "}\n"}}};
    const std::string message = compileError(fragment);
    EXPECT_NE(message.find("fragment shader: shaders/second.glsl:4"), std::string::npos) << message;
    EXPECT_NE(message.find("undeclaredThing"), std::string::npos) << message;
}

TEST(ShaderErrors, NameFirstModuleFileAndLine)
{
    auto context = createContext(Backend::Egl);
    const ShaderSource fragment{{}, {{"shaders/a.glsl", "out vec4 color;\nvoid main() { color = 1.0; }\n"}}};
    const std::string message = compileError(fragment);
    EXPECT_NE(message.find("shaders/a.glsl:2"), std::string::npos) << message;
}

TEST(ShaderErrors, ValidModulesCompile)
{
    auto context = createContext(Backend::Egl);
    const ShaderSource fragment{{}, {{"shaders/ok.glsl", "out vec4 color;\nvoid main() { color = vec4(real(1)); }\n"}}};
    EXPECT_EQ(compileError(fragment), "");
}

} // namespace
} // namespace aurorawall::gl
