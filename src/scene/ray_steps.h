#pragma once
// The ray steps of the shader (shaders/render/ray_sphere.glsl and layers.glsl) in double, for
// the components' parts of the CPU reference. Each translation unit gets its own copy (an
// unnamed namespace), and not every one uses every step.
#include "scene/component.h"

namespace aurorawall::scene::f64 {
namespace {
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include "render/ray_sphere.glsl"
#include "render/layers.glsl"
#pragma GCC diagnostic pop
} // namespace
} // namespace aurorawall::scene::f64
