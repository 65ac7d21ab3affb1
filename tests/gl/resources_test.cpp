// Textures, compute programs and the GPU timer on the EGL context.
#include "gl/context.h"
#include "gl/float_target.h"
#include "gl/full_screen_triangle.h"
#include "gl/functions.h"
#include "gl/gpu_timer.h"
#include "gl/shader_program.h"
#include "gl/texture.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <string>
#include <thread>

namespace aurorawall::gl {
namespace {

std::vector<float> ramp(size_t n)
{
    std::vector<float> values(n);
    for (size_t i = 0; i < n; ++i)
        values[i] = 0.25f + 0.5f * float(i);
    return values;
}

// A 3D lookup table read back texel by texel through a fragment shader.
TEST(Texture, Upload3DReadsBackInShader)
{
    auto context = createContext(Backend::Egl);
    const int w = 5, h = 3, d = 2;
    Texture table = Texture::create3D(w, h, d, TexelFormat::R32F, Filter::Nearest, Wrap::Clamp);
    const std::vector<float> values = ramp(size_t(w) * h * d);
    table.upload(values);
    EXPECT_THROW(table.upload({1.0f}), std::invalid_argument);

    // Target pixel (x, y) shows texel (x, y % h, y / h).
    Program program = Program::graphics(fullScreenTriangleVertexShader(), {{}, {{"table.glsl", R"(
uniform sampler3D table;
uniform int rows;
out vec4 color;
void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy);
    color = vec4(texelFetch(table, ivec3(p.x, p.y % rows, p.y / rows), 0).r);
})"}}});
    program.bindTexture("table", 3, table.id());
    program.set("rows", h);
    FloatTarget target(w, h * d);
    FullScreenTriangle triangle;
    target.bind();
    program.use();
    triangle.draw();
    const std::vector<float> pixels = target.readback();
    for (size_t i = 0; i < values.size(); ++i)
        EXPECT_EQ(pixels[4 * i], values[i]) << "texel " << i;
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST(Compute, WritesImage)
{
    auto context = createContext(Backend::Egl);
    Texture image = Texture::create2D(8, 4, TexelFormat::RGBA32F, Filter::Nearest, Wrap::Clamp);
    Program program = Program::compute({{}, {{"fill.comp", R"(
layout(local_size_x = 4, local_size_y = 4) in;
layout(rgba32f, binding = 0) uniform writeonly image2D result;
uniform vec3 scale;
void main()
{
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    imageStore(result, p, vec4(scale * vec3(p, 1.0), exp(float(p.x))));
})"}}});
    program.set("scale", glm::vec3(2, 3, 4));
    program.use();
    glBindImageTexture(0, image.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute(2, 1, 1);
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
    std::vector<float> pixels(8 * 4 * 4);
    glGetTextureImage(image.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(pixels.size() * sizeof(float)), pixels.data());
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) {
            const float* p = &pixels[4 * (y * 8 + x)];
            EXPECT_EQ(p[0], 2.0f * x);
            EXPECT_EQ(p[1], 3.0f * y);
            EXPECT_EQ(p[2], 4.0f);
            EXPECT_NEAR(p[3], std::exp(float(x)), 1e-5 * std::exp(float(x)));
        }
}

// Every uniform setter reaches the shader: pixel i of an 8x1 target shows value i.
TEST(Program, SetsUniforms)
{
    auto context = createContext(Backend::Egl);
    Program program = Program::graphics(fullScreenTriangleVertexShader(), {{}, {{"uniforms.glsl", R"(
uniform float f;
uniform int i;
uniform vec2 v2;
uniform vec3 v3;
uniform vec4 v4;
uniform mat3 m;
uniform float fs[2];
uniform vec2 v2s[2];
uniform vec4 v4s[2];
out vec4 color;
void main()
{
    vec4 values[8] = vec4[8](vec4(f, float(i), 0.0, 0.0), vec4(v2, v3.xy), vec4(v3.z, v4.xyz),
                             vec4(v4.w, m[0]), vec4(m[1], m[2].x), vec4(m[2].yz, fs[0], fs[1]),
                             vec4(v2s[0], v2s[1]), v4s[1]);
    color = values[int(gl_FragCoord.x)];
})"}}});
    program.set("f", 1.5f);
    program.set("i", -7);
    program.set("v2", glm::vec2(2, 3));
    program.set("v3", glm::vec3(4, 5, 6));
    program.set("v4", glm::vec4(7, 8, 9, 10));
    program.set("m", glm::mat3(11, 12, 13, 14, 15, 16, 17, 18, 19)); // column by column
    program.set("fs", std::vector<float>{20, 21});
    program.set("v2s", std::vector<glm::vec2>{{22, 23}, {24, 25}});
    program.set("v4s", std::vector<glm::vec4>{{0, 0, 0, 0}, {26, 27, 28, 29}});
    program.set("notInTheShader", 1.0f); // ignored, like GL
    FloatTarget target(8, 1);
    FullScreenTriangle triangle;
    target.bind();
    program.use();
    triangle.draw();
    const std::vector<float> expected = {1.5f, -7, 0, 0, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13,
                                         14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29};
    EXPECT_EQ(target.readback(), expected);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// A fragment shader that sums `iterations` sines per pixel: a draw that keeps the device busy.
Program busyProgram(int iterations)
{
    return Program::graphics(fullScreenTriangleVertexShader(), {{"ITERATIONS " + std::to_string(iterations)}, {{"busy.glsl", R"(
out vec4 color;
void main()
{
    float s = 0.0;
    for (int i = 0; i < ITERATIONS; ++i)
        s += sin(gl_FragCoord.x + float(i));
    color = vec4(s);
})"}}});
}

// The timer agrees with CPU wall time around glFinish for draws of many milliseconds: the draws are
// repeated, doubling, until they take at least 50 ms of wall time on any device, so that submitting
// and finishing (microseconds) are a small part of it.
TEST(GpuTimer, MeasuresADraw)
{
    auto context = createContext(Backend::Egl);
    Program program = busyProgram(2000);
    FloatTarget target(128, 128);
    FullScreenTriangle triangle;
    GpuTimer timer;
    if (context->rendererName().rfind("llvmpipe", 0) == 0) {
        EXPECT_FALSE(timer.usesQueries()) << "llvmpipe's timer queries undercount; the CPU clock must be used";
    }
    target.bind();
    program.use();
    triangle.draw(); // compiles the shader
    glFinish();
    double seconds = 0.0, wall = 0.0;
    for (int draws = 1; draws <= 1 << 16 && wall < 0.05; draws *= 2) {
        const auto begin = std::chrono::steady_clock::now();
        timer.start();
        for (int k = 0; k < draws; ++k)
            triangle.draw();
        seconds = timer.stopSeconds();
        glFinish();
        wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    }
    ASSERT_GE(wall, 0.05) << "65536 draws took less than 50 ms";
    EXPECT_GT(seconds, 0.5 * wall);
    EXPECT_LE(seconds, wall);
}

// What the CPU does after stop() is not counted: with queries the GPU wrote the end when it was done, without
// them stop() waited for the draw.
TEST(GpuTimer, LeavesOutCpuWorkAfterStop)
{
    auto context = createContext(Backend::Egl);
    Program program = busyProgram(500);
    FloatTarget target(64, 64);
    FullScreenTriangle triangle;
    GpuTimer timer;
    target.bind();
    program.use();
    triangle.draw(); // compiles the shader
    glFinish();
    const auto begin = std::chrono::steady_clock::now();
    timer.start();
    triangle.draw();
    timer.stop();
    const double idleSeconds = 0.2;
    std::this_thread::sleep_for(std::chrono::duration<double>(idleSeconds));
    glFinish();
    const double seconds = timer.seconds();
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    EXPECT_GT(seconds, 0.0);
    EXPECT_LT(seconds, wall - 0.9 * idleSeconds) << "the idle time after stop() was counted";
}

} // namespace
} // namespace aurorawall::gl
