#include "test_pattern.h"

#include "common/glsl.h"
#include "gl/full_screen_triangle.h"
#include "gl/shader_program.h"

#include <algorithm>
#include <cmath>
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

// Each channel's error relative to its value, u = 2^-24, with GLSL 4.60's allowances (§4.7.1: +, −, ×
// rounded, u; division 2.5 ULP; exp, exp2 3 + 2|x| ULP; log2 absolute 2^-21 on [0.5, 2], log 3 ULP
// beyond; inversesqrt 2 ULP, sqrt 1/inversesqrt, normalize and pow inherited) and Vulkan's for sin and
// cos, which GL leaves open (absolute 2^-11 on [−π, π]). p = fragCoord/size errs by 5u; n's components
// (below 1, |n.y| ≤ 0.45) by 12u absolute. Each sum is rounded up:
// - a = 2 + sin(6p.x − 3)·exp(−1.5p.y) ≥ 1: the sine's argument 39u, the sine 2^-11, the exponential
//   21u, the product and sum 4u: 2^-11 + 64u;
// - b = exp2(2.5·log2(1 + p.x·p.y)): the base 13u, so log2 2^-21 + 19u, times 2.5 and rounded, then
//   exp2 (16u) and ln 2 times the exponent's error: 64u;
// - c = 3 + n.x + n.y·cos(3p.y) ≥ 2.1: n's 24u, the cosine 18u + 2^-11 times |n.y|, the sums 8u: (0.45·2^-11 + 50u)/2.1;
// - d = log(2 + p.x) + sqrt(1 + p.y)·n.z ≥ 1.5: the logarithm 11u, the root 18u, n.z 17u, the sum 3u: 49u/1.5.
double worstErrorOverBound(const std::vector<float>& gpu, const std::vector<double>& cpu)
{
    if (gpu.size() != cpu.size())
        return 1e30;
    const double u = std::ldexp(1.0, -24), sine = std::ldexp(1.0, -11);
    const double bound[4] = {sine + 64.0 * u, 64.0 * u, (0.45 * sine + 50.0 * u) / 2.1, 49.0 * u / 1.5};
    double worst = 0;
    for (size_t i = 0; i < gpu.size(); ++i)
        worst = std::max(worst, std::abs(gpu[i] - cpu[i]) / (std::abs(cpu[i]) * bound[i % 4]));
    return worst;
}

} // namespace aurorawall::gl::test
