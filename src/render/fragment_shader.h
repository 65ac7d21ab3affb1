#pragma once
// The raymarcher's fragment shader, assembled from the modules of the components a scene lists
// (shaders/ in the data directory). A component the scene does not list contributes no code:
// neither its module nor its #define is in the source.
#include "gl/shader_program.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace aurorawall::render {

// Module file names, relative to the shader folder, in assembly order.
std::vector<std::string> fragmentModuleNames(const scene::Scene& scene);

// Reads the modules from shaderDir; throws InputError naming the file that is missing or unreadable.
gl::ShaderSource fragmentShaderSource(const scene::Scene& scene, const std::string& shaderDir);

} // namespace aurorawall::render
