#include "physics/atmosphere/shader_benchmark.h"

#include "common/data_dir.h"
#include "gl/functions.h"
#include "gl/gpu_timer.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace aurorawall::physics::atmosphere {
namespace {

using namespace gl; // the GL function pointers (gl/functions.h)

constexpr int kWorkGroupSize = 64;

const char* kPrelude = R"(layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Inputs { vec4 inputs[]; };
layout(std430, binding = 1) writeonly buffer FirstResults { vec4 firstResults[]; };
layout(std430, binding = 2) writeonly buffer Sums { vec4 sums[]; };
uniform int uItemCount;
uniform int uInvocationCount;
uniform int uRepeat;
uniform bool uCoherent;
)";

const char* kMain = R"(void main()
{
    int invocation = int(DISPATCH_INVOCATION.x);
    if (invocation >= uInvocationCount) return;
    int item = uCoherent ? (invocation / 64) % uItemCount : invocation % uItemCount;
    bool firstOfItem = uCoherent ? invocation % 64 == 0 && invocation < 64 * uItemCount : invocation < uItemCount;
    vec4 first = evaluate(item, 0.0);
    vec4 chain[BENCHMARK_CHAINS];
    for (int c = 0; c < BENCHMARK_CHAINS; ++c) chain[c] = first + vec4(float(c));
    for (int k = BENCHMARK_CHAINS; k < uRepeat; k += BENCHMARK_CHAINS) {
        for (int c = 0; c < BENCHMARK_CHAINS; ++c)
            chain[c] += evaluate(item, float(floatBitsToUint(chain[c].x) & 1u) * 1e-30);
    }
    vec4 sum = chain[0];
    for (int c = 1; c < BENCHMARK_CHAINS; ++c) sum += chain[c];
    if (firstOfItem) firstResults[item] = first;
    sums[invocation] = sum;
}
)";

// A buffer object of the given size in bytes (initial data optional), bound to an SSBO binding point.
GLuint createStorageBuffer(GLsizeiptr bytes, const void* data, GLuint binding)
{
    GLuint buffer = 0;
    glCreateBuffers(1, &buffer);
    glNamedBufferStorage(buffer, bytes, data, 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, buffer);
    return buffer;
}

} // namespace

ShaderBenchmarkResult runShaderBenchmark(const gl::ShaderSource& source, const std::vector<glm::vec4>& inputs,
                                         int itemCount, const ShaderBenchmarkSettings& settings,
                                         const std::function<void(gl::Program&)>& setUniforms)
{
    gl::ShaderSource full = source;
    full.defines.push_back("BENCHMARK_CHAINS " + std::to_string(settings.chains));
    full.modules.insert(full.modules.begin(), {"benchmark_prelude.comp", kPrelude});
    full.modules.push_back({"benchmark_main.comp", kMain});
    gl::Program program = gl::Program::compute(full);
    const int invocations = itemCount * settings.copies * (settings.coherent ? kWorkGroupSize : 1);
    program.set("uItemCount", itemCount);
    program.set("uInvocationCount", invocations);
    program.set("uRepeat", settings.repeat);
    program.set("uCoherent", settings.coherent ? 1 : 0);
    setUniforms(program);

    GLuint buffers[3] = {
        createStorageBuffer(GLsizeiptr(inputs.size() * sizeof(glm::vec4)), inputs.data(), 0),
        createStorageBuffer(GLsizeiptr(itemCount) * GLsizeiptr(sizeof(glm::vec4)), nullptr, 1),
        createStorageBuffer(GLsizeiptr(invocations) * GLsizeiptr(sizeof(glm::vec4)), nullptr, 2)};
    program.use();
    const GLuint groups = GLuint((invocations + kWorkGroupSize - 1) / kWorkGroupSize);
    gl::GpuTimer timer;
    ShaderBenchmarkResult result;
    for (int run = 0; run <= settings.runs; ++run) { // run 0 warms up
        timer.start();
        glDispatchCompute(groups, 1, 1);
        double seconds = timer.stopSeconds();
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT); // each run writes the outputs anew
        if (run == 1 || (run > 1 && seconds < result.seconds)) result.seconds = seconds;
    }
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    result.firstResults.resize(size_t(itemCount));
    glGetNamedBufferSubData(buffers[1], 0, GLsizeiptr(itemCount) * GLsizeiptr(sizeof(glm::vec4)),
                            result.firstResults.data());
    glDeleteBuffers(3, buffers);
    glUseProgram(0);
    return result;
}

double nanosecondsPerEvaluation(const ShaderBenchmarkResult& result, const ShaderBenchmarkResult& baseline,
                                int itemCount, const ShaderBenchmarkSettings& settings)
{
    const int perInvocation = 1 + settings.chains * ((settings.repeat + settings.chains - 1) / settings.chains - 1);
    double evaluations = double(itemCount) * double(settings.copies) * double(perInvocation) *
                         (settings.coherent ? kWorkGroupSize : 1);
    return (result.seconds - baseline.seconds) * 1e9 / evaluations;
}

gl::ShaderModule readShaderModule(const std::string& relativePath)
{
    return gl::readShaderModule(common::dataDirectory() + "/shaders/" + relativePath);
}

} // namespace aurorawall::physics::atmosphere
