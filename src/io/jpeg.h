#pragma once
// Reading JPEG images (libjpeg-turbo): the planet's night-lights texture from Debian's
// xplanet-images ships as JPEG.
#include "io/image.h"

#include <string>

namespace aurorawall::io {

// Decodes an 8-bit JPEG (greyscale or colour) to RGBA floats in [0, 1] holding the ENCODED
// (sRGB) values, rows top-down, alpha 1. Throws std::runtime_error naming the file.
Image readJpeg(const std::string& path);

} // namespace aurorawall::io
