#include "gl/shader_program.h"

#include "common/input_error.h"
#include "gl/debug_layer.h"
#include "gl/functions.h"

#include <glm/gtc/type_ptr.hpp>

#include <fstream>
#include <regex>
#include <sstream>
#include <utility>

namespace aurorawall::gl {
namespace {

// Module k (1-based) is source string k and starts at line k * kLineStride + 1, so its location
// survives drivers that drop the source-string number (Mesa 22 reports every string as 0).
constexpr int kLineStride = 100000;

// A compute shader's index of its invocation in the dispatch: gl_GlobalInvocationID, or with the
// debug mode reverse-workgroups (debug_layer.h) the same with the workgroups numbered from the last.
// A macro, since gl_WorkGroupSize may be used only after the shader's local_size layout.
const char* const kDispatchInvocation = R"(#ifdef AURORAWALL_REVERSE_WORKGROUPS
#define DISPATCH_INVOCATION ((gl_NumWorkGroups - 1u - gl_WorkGroupID) * gl_WorkGroupSize + gl_LocalInvocationID)
#else
#define DISPATCH_INVOCATION gl_GlobalInvocationID
#endif
)";

// Source string 0 is the preamble; module k is string k.
std::vector<std::string> assemble(GLenum stage, const ShaderSource& source)
{
    std::string preamble = "#version 450 core\n";
    for (const std::string& extension : source.extensions)
        preamble += "#extension " + extension + " : require\n";
    preamble += "#define real float\n";
    if (stage == GL_COMPUTE_SHADER) {
        if (installedDebugModes().reverseWorkgroups)
            preamble += "#define AURORAWALL_REVERSE_WORKGROUPS\n";
        preamble += kDispatchInvocation;
    }
    for (const std::string& define : source.defines)
        preamble += "#define " + define + "\n";
    std::vector<std::string> strings{preamble};
    for (size_t k = 0; k < source.modules.size(); ++k)
        strings.push_back("#line " + std::to_string((k + 1) * kLineStride + 1) + " " + std::to_string(k + 1) + "\n" +
                          source.modules[k].text + "\n");
    return strings;
}

// "file:line" for the driver's source-string number and line.
std::string fileAndLine(const ShaderSource& source, long string, long line)
{
    const long module = line / kLineStride;
    if (module >= 1 && module <= static_cast<long>(source.modules.size()))
        return source.modules[module - 1].file + ":" + std::to_string(line % kLineStride);
    return (string == 0 ? "<preamble>" : "<source " + std::to_string(string) + ">") + ":" + std::to_string(line);
}

// Rewrites driver locations "S:L" and "S(L)" at the start of a log line (after an optional
// "ERROR: " or "WARNING: ") into "file:line".
std::string mapLog(const std::string& log, const ShaderSource& source)
{
    static const std::regex location(R"(^((?:ERROR: |WARNING: )?)(\d+)(?::(\d+)|\((\d+)\)))");
    std::istringstream lines(log);
    std::string line, mapped;
    while (std::getline(lines, line)) {
        std::smatch m;
        if (std::regex_search(line, m, location)) {
            const long lineNo = std::stol(m[3].matched ? m[3].str() : m[4].str());
            line = m[1].str() + fileAndLine(source, std::stol(m[2].str()), lineNo) + m.suffix().str();
        }
        if (!line.empty())
            mapped += line + "\n";
    }
    return mapped;
}

// The info log of a shader or a program, read with that object's pair of GL calls
// (glGetShaderiv and glGetShaderInfoLog, or glGetProgramiv and glGetProgramInfoLog).
template <class GetParameter, class GetInfoLog>
std::string infoLog(GLuint object, GetParameter getParameter, GetInfoLog getInfoLog)
{
    GLint length = 0;
    getParameter(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(length > 0 ? length : 1), '\0');
    getInfoLog(object, length, nullptr, log.data());
    return log.c_str();
}

std::string stageName(GLenum stage)
{
    switch (stage) {
    case GL_VERTEX_SHADER: return "vertex shader";
    case GL_FRAGMENT_SHADER: return "fragment shader";
    case GL_COMPUTE_SHADER: return "compute shader";
    default: return "shader";
    }
}

GLuint compile(GLenum stage, const ShaderSource& source)
{
    const std::vector<std::string> strings = assemble(stage, source);
    std::vector<const GLchar*> pointers;
    for (const std::string& s : strings)
        pointers.push_back(s.c_str());
    GLuint shader = glCreateShader(stage);
    glShaderSource(shader, static_cast<GLsizei>(pointers.size()), pointers.data(), nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        const std::string log = mapLog(infoLog(shader, glGetShaderiv, glGetShaderInfoLog), source);
        glDeleteShader(shader);
        throw ShaderError(stageName(stage) + ": " + log);
    }
    return shader;
}

GLuint link(const std::vector<GLuint>& shaders)
{
    GLuint program = glCreateProgram();
    for (GLuint s : shaders)
        glAttachShader(program, s);
    glLinkProgram(program);
    for (GLuint s : shaders) {
        glDetachShader(program, s);
        glDeleteShader(s);
    }
    GLint ok = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        const std::string log = infoLog(program, glGetProgramiv, glGetProgramInfoLog);
        glDeleteProgram(program);
        throw ShaderError("link: " + log);
    }
    return program;
}

} // namespace

ShaderModule readShaderModule(const std::string& path)
{
    std::ifstream file(path);
    std::ostringstream text;
    if (!file || !(text << file.rdbuf()))
        throw common::inputError(path, 0, "cannot read shader module (check --data-dir or AURORAWALL_DATA_DIR)");
    return {path, text.str()};
}

ShaderSource fullScreenTriangleVertexShader()
{
    // Vertices (-1,-1), (3,-1), (-1,3): one triangle covering the viewport.
    return {{}, {{"<full-screen triangle>", R"(
void main()
{
    vec2 corner = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    gl_Position = vec4(2.0 * corner - 1.0, 0.0, 1.0);
})"}}};
}

Program Program::graphics(const ShaderSource& vertex, const ShaderSource& fragment)
{
    GLuint vs = compile(GL_VERTEX_SHADER, vertex);
    GLuint fs = 0;
    try {
        fs = compile(GL_FRAGMENT_SHADER, fragment);
    } catch (...) {
        glDeleteShader(vs);
        throw;
    }
    return Program(link({vs, fs}));
}

Program Program::compute(const ShaderSource& source)
{
    return Program(link({compile(GL_COMPUTE_SHADER, source)}));
}

Program::Program(Program&& other) noexcept
    : id_(std::exchange(other.id_, 0)), locations_(std::move(other.locations_))
{
}

Program& Program::operator=(Program&& other) noexcept
{
    std::swap(id_, other.id_);
    std::swap(locations_, other.locations_);
    return *this;
}

Program::~Program()
{
    if (id_)
        glDeleteProgram(id_);
}

void Program::use() const { glUseProgram(id_); }

GLint Program::location(const std::string& name)
{
    auto it = locations_.find(name);
    if (it == locations_.end())
        it = locations_.emplace(name, glGetUniformLocation(id_, name.c_str())).first;
    return it->second;
}

void Program::set(const std::string& name, float value) { glProgramUniform1f(id_, location(name), value); }
void Program::set(const std::string& name, int value) { glProgramUniform1i(id_, location(name), value); }

void Program::set(const std::string& name, const glm::vec2& value)
{
    glProgramUniform2fv(id_, location(name), 1, glm::value_ptr(value));
}

void Program::set(const std::string& name, const glm::ivec2& value)
{
    glProgramUniform2iv(id_, location(name), 1, glm::value_ptr(value));
}

void Program::set(const std::string& name, const glm::vec3& value)
{
    glProgramUniform3fv(id_, location(name), 1, glm::value_ptr(value));
}

void Program::set(const std::string& name, const glm::vec4& value)
{
    glProgramUniform4fv(id_, location(name), 1, glm::value_ptr(value));
}

void Program::set(const std::string& name, const glm::mat3& value)
{
    glProgramUniformMatrix3fv(id_, location(name), 1, GL_FALSE, glm::value_ptr(value));
}

void Program::set(const std::string& name, const std::vector<float>& values)
{
    glProgramUniform1fv(id_, location(name), GLsizei(values.size()), values.data());
}

void Program::set(const std::string& name, const std::vector<glm::vec2>& values)
{
    glProgramUniform2fv(id_, location(name), GLsizei(values.size()),
                        reinterpret_cast<const GLfloat*>(values.data()));
}

void Program::set(const std::string& name, const std::vector<glm::vec4>& values)
{
    glProgramUniform4fv(id_, location(name), GLsizei(values.size()),
                        reinterpret_cast<const GLfloat*>(values.data()));
}

void Program::bindTexture(const std::string& name, int unit, GLuint texture)
{
    glBindTextureUnit(static_cast<GLuint>(unit), texture);
    set(name, unit);
}

} // namespace aurorawall::gl
