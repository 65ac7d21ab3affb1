#include "components/planet_texture/night_lights.h"

#include "io/jpeg.h"

#include <chrono>
#include <cmath>
#include <filesystem>

namespace aurorawall::components::planet_texture {

namespace {

// sRGB-encoded texel to linear (IEC 61966-2-1).
float srgbDecode(float v)
{
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

} // namespace

NightLights::NightLights(const Settings& planet)
{
    const auto start = std::chrono::steady_clock::now();
    if (!std::filesystem::is_regular_file(planet.nightImage)) {
        summary_ = "planet_texture: " + planet.nightImage + " not found (install xplanet-images); uniform ground";
        texture_ = std::make_unique<gl::Texture>(
            gl::Texture::create2D(1, 1, gl::TexelFormat::RGB32F, gl::Filter::Nearest, gl::Wrap::Repeat));
        texture_->upload({0.0f, 0.0f, 0.0f});
        return;
    }
    const io::Image image = io::readJpeg(planet.nightImage);
    // GL's first row is the bottom (latitude -90): flip the top-down image rows.
    std::vector<float> texels(3 * size_t(image.width) * image.height);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c)
                texels[3 * (size_t(image.height - 1 - y) * image.width + x) + c] = srgbDecode(image.pixel(x, y)[c]);
    texture_ = std::make_unique<gl::Texture>(gl::Texture::create2D(image.width, image.height, gl::TexelFormat::RGB32F,
                                                                   gl::Filter::Linear, gl::Wrap::Repeat));
    texture_->upload(texels);
    radiance_ = static_cast<float>(planet.nightLightsRadiance);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    summary_ = "planet_texture: " + planet.nightImage + " " + std::to_string(image.width) + " x " +
               std::to_string(image.height) + ": " + std::to_string(static_cast<long>(ms)) + " ms";
}

void NightLights::bind(gl::Program& program) const
{
    program.bindTexture("uNightLights", 2, texture_->id());
    program.set("uNightLightsRadiance", radiance_);
}

} // namespace aurorawall::components::planet_texture
