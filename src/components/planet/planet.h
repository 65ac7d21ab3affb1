#pragma once
// The planet component: a sphere centred at the origin (its radius is the scene's
// planetRadiusKm) whose night ground is dimly lit; it ends every ray that meets it.
#include "scene/component.h"

#include <glm/glm.hpp>

namespace aurorawall::components::planet {

struct Settings : scene::SettingsOf<Settings> {
    static constexpr const char* kComponent = "planet";
    // Night ground lit by starlight, airglow and aurora (cd/m^2; snow under a moonless sky is ~1e-5).
    glm::dvec3 surfaceRadiance{2.0e-5, 2.5e-5, 3.5e-5};
};

const scene::Component& component();

} // namespace aurorawall::components::planet
