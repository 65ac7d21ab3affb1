#pragma once
// Every registered scene component (src/components/CMakeLists.txt lists them), in registry order.
#include "scene/scene.h"

#include <string>

namespace aurorawall::components {

const scene::Registry& registry();

// Reads a scene file with the registered components (scene::loadScene).
scene::Scene loadScene(const std::string& path);

} // namespace aurorawall::components
