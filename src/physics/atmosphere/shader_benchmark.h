#pragma once
// Cost of a GLSL function measured inside a compute shader, and its float results as the GPU
// computes them. Works on any GL 4.5 context: llvmpipe here, a GPU when one is lent.
//
// The caller's source defines `vec4 evaluate(int item, float jitter)`, which reads its inputs from
// `inputs[]` (a std430 buffer of vec4, declared by the harness before the caller's modules). The
// harness runs invocation i on item i mod itemCount (`copies` copies of the item set, so a GPU can be
// filled): neighbouring invocations, which share SIMD lanes, take different items and pay for each
// other's branches. With `coherent`, each work group of 64 invocations takes one item (64 times as
// many invocations): the cost of a smooth image, where neighbouring pixels take the same branches.
// Each invocation calls evaluate about `repeat` times. Each call after the first gets jitter = 0 or 1e-30
// taken from the lowest bit of a running sum, a dependency chain the compiler can neither hoist out of
// the loop nor merge; the sums are stored, so nothing is eliminated. With `chains` = 1 every call waits
// for the previous one (the latency of the function); with several chains the calls of different chains
// are independent and can overlap, as independent pixels do (its throughput). Time: GpuTimer (timestamp
// queries on a GPU; glFinish and the CPU clock on llvmpipe, whose timer queries are wrong), the
// fastest of `runs` dispatches after one warm-up dispatch (which also compiles on llvmpipe).
#include "gl/shader_program.h"

#include <glm/glm.hpp>

#include <functional>
#include <string>
#include <vector>

namespace aurorawall::physics::atmosphere {

struct ShaderBenchmarkSettings {
    int repeat = 1;  // evaluate() calls per invocation
    int copies = 1;  // invocations = copies × items
    int runs = 3;    // timed dispatches; the fastest counts
    bool coherent = false; // a work group of 64 invocations per item
    int chains = 1;  // independent dependency chains per invocation (see above)
};

struct ShaderBenchmarkResult {
    double seconds = 0.0;                // one dispatch
    std::vector<glm::vec4> firstResults; // evaluate(item, 0) for every item, read back
};

// Needs a current GL 4.5 context. setUniforms is called once with the linked program.
// Throws gl::ShaderError when the source does not compile.
ShaderBenchmarkResult runShaderBenchmark(const gl::ShaderSource& source, const std::vector<glm::vec4>& inputs,
                                         int itemCount, const ShaderBenchmarkSettings& settings,
                                         const std::function<void(gl::Program&)>& setUniforms);

// Nanoseconds per evaluation: (seconds − baseline seconds) / (invocations × calls per invocation), where
// an invocation makes 1 + chains·(⌈repeat/chains⌉ − 1) calls (repeat when chains = 1).
double nanosecondsPerEvaluation(const ShaderBenchmarkResult& result, const ShaderBenchmarkResult& baseline,
                                int itemCount, const ShaderBenchmarkSettings& settings);

// A shader module read from dataDirectory()/shaders/<relativePath> — the files the C++ side includes.
// Throws aurorawall::InputError naming the file when it cannot be read (gl::readShaderModule).
gl::ShaderModule readShaderModule(const std::string& relativePath);

} // namespace aurorawall::physics::atmosphere
