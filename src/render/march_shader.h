#pragma once
// The raymarcher's shader, assembled from the components a scene lists: their modules in registry
// order, then shadeRay, generated to pass each pixel's ray through the components' geometry steps
// and then their shading steps in compositing order (src/scene/compositing_order.h), then the pixel's
// shading (render/pixel.glsl) and the entry point of the stage it runs in: a fragment shader over a
// full-screen triangle (render/main.frag) or a compute shader (render/main.comp), the same text but
// for how each finds its pixel and writes it. A component the scene does not list contributes no
// code: neither its modules, nor its #define HAS_<NAME>, nor those of the roles it provides
// (HAS_CURTAIN_DETAIL for "curtain detail"), nor a call.
#include "gl/shader_program.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace aurorawall::render {

// The shader stage the march runs in.
enum class MarchStage { Fragment, Compute };

// The faster stage on the renderer named (GL_RENDERER): Fragment on Mesa's CPU renderers (llvmpipe,
// softpipe), which run a fragment shader's pixels in their own threads with less overhead than a
// compute dispatch's workgroups; Compute elsewhere (on NVIDIA H100/H200 only a few multiprocessors
// run fragment shaders). Measured: docs/BENCHMARKS.md, "The march as a compute shader".
MarchStage preferredMarchStage(const std::string& rendererName);

// Module file names, relative to the shader folder, in assembly order (shadeRay comes after the
// components' modules and before render/pixel.glsl and the entry point, render/main.frag or
// render/main.comp).
std::vector<std::string> marchModuleNames(const scene::Scene& scene, MarchStage stage = MarchStage::Fragment);

// The generated shadeRay(origin, direction) for the scene's components.
std::string compositingSource(const scene::Scene& scene);

// Reads the modules from shaderDir; throws InputError naming the file that is missing or unreadable.
gl::ShaderSource marchShaderSource(const scene::Scene& scene, const std::string& shaderDir,
                                   MarchStage stage = MarchStage::Fragment);

} // namespace aurorawall::render
