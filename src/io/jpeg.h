#pragma once
// Reading JPEG images (libjpeg-turbo): the planet's night-lights texture from Debian's
// xplanet-images ships as JPEG.
#include "io/image.h"

#include <string>

namespace aurorawall::io {

// The largest side read: the side of the largest texture every OpenGL 4.5 device holds.
constexpr unsigned kMaxJpegSide = 16384;

// Decodes an 8-bit JPEG (greyscale or colour) to RGBA floats in [0, 1] holding the ENCODED
// (sRGB) values, rows top-down, alpha 1. Throws std::runtime_error naming the file for
// a file that cannot be read, corrupt or truncated data, or a side over kMaxJpegSide.
Image readJpeg(const std::string& path);

} // namespace aurorawall::io
