#pragma once
// Screen pixels as they travel between ranks (load-balanced bands, the gathered wall) and as the EXR
// files store them: linear RGB as IEEE half floats (OpenEXR's `half`, 2^-11 relative precision above
// 2^-14, steps of 2^-24 below: in cd/m², 0.3 R of the green line), with
// one documented clamp: NaN -> 0, values beyond +-HALF_MAX (65504, infinities included) -> +-HALF_MAX.
// 6 bytes a pixel instead of 16 for float RGBA. Rendered alpha is always 1, so it does not travel.
#include "io/image.h"

#include <cstdint>
#include <vector>

namespace aurorawall::io {

// The bits of the half nearest to `value` after the clamp above.
std::uint16_t halfBits(float value);

// R, G, B halves per pixel, rows as in the image.
std::vector<std::uint16_t> packRgbHalf(const Image& image);

// The image those halves hold, alpha 1. Throws std::invalid_argument unless rgb holds 3 * width * height.
Image unpackRgbHalf(int width, int height, const std::vector<std::uint16_t>& rgb);

// unpackRgbHalf(packRgbHalf(image)) with image's alpha set to 1: the pixels every rank ends up with.
Image roundedToHalf(const Image& image);

} // namespace aurorawall::io
