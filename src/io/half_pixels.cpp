#include "io/half_pixels.h"

#include <half.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace aurorawall::io {

std::uint16_t halfBits(float value)
{
    const float halfMax = float(HALF_MAX);
    return half(std::isnan(value) ? 0.0f : std::clamp(value, -halfMax, halfMax)).bits();
}

std::vector<std::uint16_t> packRgbHalf(const Image& image)
{
    const std::size_t pixels = std::size_t(image.width) * image.height;
    std::vector<std::uint16_t> rgb(3 * pixels);
    for (std::size_t i = 0; i < pixels; ++i)
        for (int c = 0; c < 3; ++c)
            rgb[3 * i + c] = halfBits(image.rgba[4 * i + c]);
    return rgb;
}

Image unpackRgbHalf(int width, int height, const std::vector<std::uint16_t>& rgb)
{
    Image image(width, height);
    const std::size_t pixels = std::size_t(width) * height;
    if (rgb.size() != 3 * pixels)
        throw std::invalid_argument("unpackRgbHalf: " + std::to_string(rgb.size()) + " halves for a " +
                                    std::to_string(width) + "x" + std::to_string(height) + " image");
    for (std::size_t i = 0; i < pixels; ++i) {
        for (int c = 0; c < 3; ++c) {
            half h;
            h.setBits(rgb[3 * i + c]);
            image.rgba[4 * i + c] = float(h);
        }
        image.rgba[4 * i + 3] = 1.0f;
    }
    return image;
}

Image roundedToHalf(const Image& image)
{
    return unpackRgbHalf(image.width, image.height, packRgbHalf(image));
}

} // namespace aurorawall::io
