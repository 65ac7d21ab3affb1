#include "test_pattern.h"

#include "common/glsl.h"
#include "gl/full_screen_triangle.h"
#include "gl/shader_program.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace aurorawall::f64 {
AURORAWALL_GLSL_PRECISION(double)
#include "pattern.glsl"
} // namespace aurorawall::f64

namespace aurorawall::gl::test {

std::string readTestFile(const std::string& name)
{
    std::ifstream in(std::string(AURORAWALL_GL_TEST_DIR) + "/" + name);
    if (!in)
        throw std::runtime_error("cannot read tests/gl/" + name);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

void drawPattern(const FloatTarget& target)
{
    const ShaderSource fragment{{},
                                {{"tests/gl/pattern.glsl", readTestFile("pattern.glsl")},
                                 {"tests/gl/pattern_main.glsl", R"(
uniform vec2 size;
out vec4 color;
void main() { color = testPattern(gl_FragCoord.xy, size); }
)"}}};
    Program program = Program::graphics(fullScreenTriangleVertexShader(), fragment);
    program.set("size", glm::vec2(kWidth, kHeight));
    FullScreenTriangle triangle;
    target.bind();
    program.use();
    triangle.draw();
}

std::vector<float> renderPattern()
{
    FloatTarget target(kWidth, kHeight);
    drawPattern(target);
    return target.readback();
}

std::vector<double> referencePattern()
{
    std::vector<double> pixels;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const glm::dvec4 v = f64::testPattern({x + 0.5, y + 0.5}, {kWidth, kHeight});
            pixels.insert(pixels.end(), {v.x, v.y, v.z, v.w});
        }
    return pixels;
}

double maxRelativeError(const std::vector<float>& gpu, const std::vector<double>& cpu)
{
    if (gpu.size() != cpu.size())
        return 1e30;
    double worst = 0;
    for (size_t i = 0; i < gpu.size(); ++i)
        worst = std::max(worst, std::abs(gpu[i] - cpu[i]) / std::abs(cpu[i]));
    return worst;
}

} // namespace aurorawall::gl::test
