#pragma once
// OpenEXR files: linear radiance as HALF floats, ZIP compressed, one scan-line part.
#include "io/image.h"

#include <string>

namespace aurorawall::io {

enum class ExrChannels { RGB, RGBA };

// Writes `image` atomically (see atomic_file.h). HALF can hold magnitudes up to HALF_MAX = 65504
// with a relative precision of 2^-11 down to 2^-14 (6.1e-5), and below that in steps of 2^-24 (6e-8:
// in cd/m², 0.3 R of the aurora's green line); larger values (and +-inf) are clamped to +-HALF_MAX
// rather than becoming inf, and NaN is written as 0, so every stored value is finite.
// Throws std::invalid_argument for an empty or inconsistent image, std::runtime_error on I/O errors.
void writeExr(const std::string& path, const Image& image, ExrChannels channels = ExrChannels::RGB);

// Reads any RGB(A) EXR file; a file without alpha reads with alpha 1. Throws std::runtime_error.
Image readExr(const std::string& path);

} // namespace aurorawall::io
