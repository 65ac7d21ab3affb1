#pragma once
// The planet_texture component: the night side's city lights as an equirectangular texture
// (longitude -180..180 deg left to right, latitude 90..-90 top to bottom, as xplanet's images).
// If the image is missing (xplanet-images not installed) the ground stays uniform and the
// summary says so: a documented fallback, not an error.
#include "gl/shader_program.h"
#include "gl/texture.h"
#include "components/planet_texture/planet_texture.h"

#include <memory>
#include <string>

namespace aurorawall::components::planet_texture {

class NightLights {
public:
    explicit NightLights(const Settings& planet);

    // Texture unit 2; uNightLightsRadiance is 0 when there is no image.
    void bind(gl::Program& program) const;

    const std::string& summary() const { return summary_; }

private:
    std::unique_ptr<gl::Texture> texture_;
    float radiance_ = 0.0f;
    std::string summary_;
};

} // namespace aurorawall::components::planet_texture
