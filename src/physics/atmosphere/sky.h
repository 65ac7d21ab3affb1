#pragma once
// Single-scattering sky lit by several sources. The shader text is
// shaders/physics/atmosphere/sky.glsl; this header evaluates the same text on the CPU in float (the GPU's
// arithmetic) and in double (the reference).
#include "physics/atmosphere/airmass.h"

#include <glm/glm.hpp>
#include <vector>

namespace aurorawall::physics::atmosphere {

inline constexpr int kSkyMaxLights = 8; // SKY_MAX_LIGHTS in sky.glsl

// The air: exponential density between the ground and the top sphere, Rayleigh scattering only.
struct SkyAtmosphereParameters {
    double planetRadiusKm = 6371.0;
    double topRadiusKm = 6371.0 + 100.0;
    double scaleHeightKm = 8.0;
    // β at the ground per km for the R, G, B primaries (Bruneton & Neyret 2008; the scene's
    // atmosphere.extinctionPerKm: for pure Rayleigh air, extinction = scattering).
    glm::dvec3 rayleighScatteringPerKm{5.8e-3, 13.5e-3, 33.1e-3};
};

// A distant light (Sun, Moon): the unit vector toward it in the planet frame and its illuminance at
// the top of the atmosphere in lux per linear-sRGB primary (a white Sun: 1.28e5 on each).
struct SkyLight {
    glm::dvec3 direction{0.0, 0.0, 1.0};
    glm::dvec3 illuminanceLux{0.0};
};

// A view ray: origin (km, planet frame), direction (any length) and its far end tMax (km).
struct SkyView {
    glm::dvec3 origin{0.0};
    glm::dvec3 direction{0.0, 0.0, 1.0};
    double tMax = 1e30;
};

enum class SkyLightMethod { ClosedForm, NestedMarch };

// The sky radiance in cd/m² per primary (skyScattering in sky.glsl) with viewSteps outer steps and,
// for the nested march, lightSteps inner steps per light. At most kSkyMaxLights lights.
// Float32 rounds every input to float and runs the float instantiation of the module.
glm::dvec3 skyRadiance(const SkyView& view, const SkyAtmosphereParameters& atmosphere,
                       const std::vector<SkyLight>& lights, SkyLightMethod method, int viewSteps, int lightSteps,
                       AirmassPrecision precision);

} // namespace aurorawall::physics::atmosphere
