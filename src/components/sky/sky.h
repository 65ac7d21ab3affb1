#pragma once
// The sky component: single Rayleigh scattering in the atmosphere component's air, lit by up to
// 8 sources, each source's light-side optical depth from the closed-form airmass (several lights
// for the price of one).
#include "scene/component.h"

#include <glm/glm.hpp>

#include <vector>

namespace aurorawall::components::sky {

// A light source: a direction in the planet frame and its illuminance above the atmosphere, per
// linear-sRGB primary (lux).
struct Light {
    glm::dvec3 direction{0.0, 0.0, 1.0};
    glm::dvec3 illuminanceLux{1.28e5};
};

struct Settings : scene::SettingsOf<Settings> {
    static constexpr const char* kComponent = "sky";
    int viewSteps = 16;       // march steps along the view ray
    bool nestedMarch = false; // light-side depth by an inner march of lightSteps instead (the reference)
    int lightSteps = 8;
    std::vector<Light> lights;
};

const scene::Component& component();

} // namespace aurorawall::components::sky
