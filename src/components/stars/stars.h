#pragma once
// The stars component: a fixed random star field on the celestial sphere behind everything.
#include "scene/component.h"

namespace aurorawall::components::stars {

struct Settings : scene::SettingsOf<Settings> {
    static constexpr const char* kComponent = "stars";
    double density = 0.004;        // probability that a direction cell holds a star
    double brightnessCdM2 = 0.05;  // radiance at the centre of the brightest star, cd/m^2
};

const scene::Component& component();

} // namespace aurorawall::components::stars
