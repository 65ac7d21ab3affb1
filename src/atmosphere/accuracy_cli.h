#pragma once
// `aurorawall accuracy --airmass | --sky`: accuracy and shader cost of the airmass methods (issue 4,
// part 4) and of the several-lights sky (part 6), as docs/ACCURACY.md shows them.
#include "atmosphere/airmass.h"

#include <iosfwd>
#include <string>
#include <vector>

namespace aurorawall {

// An airmass method's GLSL (AirmassMethod::glslFunction) evaluated once per ray in a compute shader on
// the current GL 4.5 context, the float results read back (the rays' inputs rounded to float).
// Throws gl::ShaderError when the shader does not compile.
std::vector<double> evaluateAirmassInShader(const std::string& glslFunction, const std::vector<AirmassRay>& rays);

// argv[0] is the command's name ("accuracy"). Opens a headless EGL context (llvmpipe here, the GPU
// where there is one), times the shared GLSL modules in a compute shader, reads their float results
// back and compares them, and the CPU float32/float64 evaluations of the same text, with the double
// reference. Returns 0; 2 with one line on `err` for a bad option; 1 with one line when no GL
// context or shader can be made.
int runAccuracyCommand(int argc, char** argv, std::ostream& out, std::ostream& err);

} // namespace aurorawall
