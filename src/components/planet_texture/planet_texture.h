#pragma once
// The planet_texture component: the night side's city lights on the ground.
#include "scene/component.h"

#include <string>

namespace aurorawall::components::planet_texture {

struct Settings : scene::SettingsOf<Settings> {
    static constexpr const char* kComponent = "planet_texture";
    // An equirectangular image, Debian's xplanet-images by default; if it is not installed the
    // ground stays uniform.
    std::string nightImage = "/usr/share/xplanet/images/night.jpg";
    double nightLightsRadiance = 5.0e-4; // cd/m^2 of a white texel
};

const scene::Component& component();

} // namespace aurorawall::components::planet_texture
