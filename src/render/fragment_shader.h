#pragma once
// The raymarcher's fragment shader, assembled from the components a scene lists: their modules in
// registry order, then shadeRay, generated to pass each pixel's ray through the components'
// geometry steps and then their shading steps in compositing order (src/scene/component.h).
// A component the scene does not list contributes no code: neither its modules, nor its
// #define HAS_<NAME>, nor a call.
#include "gl/shader_program.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace aurorawall::render {

// Module file names, relative to the shader folder, in assembly order (shadeRay comes after the
// components' modules and before render/main.frag).
std::vector<std::string> fragmentModuleNames(const scene::Scene& scene);

// The generated shadeRay(origin, direction) for the scene's components.
std::string compositingSource(const scene::Scene& scene);

// Reads the modules from shaderDir; throws InputError naming the file that is missing or unreadable.
gl::ShaderSource fragmentShaderSource(const scene::Scene& scene, const std::string& shaderDir);

} // namespace aurorawall::render
