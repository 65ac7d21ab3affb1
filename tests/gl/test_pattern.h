#pragma once
// Renders pattern.glsl into a float target and evaluates it on the CPU in double precision.
#include "gl/float_target.h"

#include <string>
#include <vector>

namespace aurorawall::gl::test {

constexpr int kWidth = 97, kHeight = 61;

// Draws the pattern into `target` (kWidth x kHeight) with the current context.
void drawPattern(const FloatTarget& target);

// Draws it into a new FloatTarget and reads it back.
std::vector<float> renderPattern();

// The same pixels in double precision, in FloatTarget's bottom-up row order.
std::vector<double> referencePattern();

// Largest |gpu - cpu| / |cpu| over all pixels and channels, each channel's divided by what GLSL's
// float arithmetic allows it: at most 1 on any conforming device.
double worstErrorOverBound(const std::vector<float>& gpu, const std::vector<double>& cpu);

// Text of a file in tests/gl.
std::string readTestFile(const std::string& name);

} // namespace aurorawall::gl::test
