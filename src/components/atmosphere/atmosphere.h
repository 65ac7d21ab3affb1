#pragma once
// The atmosphere component: the lower atmosphere, an exponential density from the ground up to
// its top, which attenuates what lies behind it and adds the night sky's glow. The one air model
// of the scene: the sky component scatters light in this same air.
#include "scene/component.h"

#include <glm/glm.hpp>

namespace aurorawall::components::atmosphere {

struct Settings : scene::SettingsOf<Settings> {
    static constexpr const char* kComponent = "atmosphere";
    double topKm = 75.0;
    double scaleHeightKm = 8.0;
    // Rayleigh extinction at sea level per km for the R, G, B primaries (Bruneton & Neyret 2008).
    glm::dvec3 extinctionPerKm{5.8e-3, 13.5e-3, 33.1e-3};
    // Night-sky glow (cd/m^2): airglow and starlight scattered by the air. A path of transmittance
    // T adds skyGlow (1 - T), so an optically thick path near the horizon tends to skyGlow and the
    // zenith sky comes out near 2e-5 cd/m^2 and the horizon near 2e-4 cd/m^2 (a dark natural night
    // sky is about 1e-4 cd/m^2, 22 mag/arcsec^2).
    glm::dvec3 skyGlow{1.5e-4, 2.0e-4, 2.5e-4};
};

const scene::Component& component();

} // namespace aurorawall::components::atmosphere
