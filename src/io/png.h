#pragma once
// 8-bit sRGB PNG previews of linear images.
#include "io/image.h"
#include "io/tone_map.h"

#include <cstdint>
#include <string>
#include <vector>

namespace aurorawall::io {

// Tone maps each pixel with toneMapPixel, quantises to 8 bits (round(255 v)) and writes an opaque
// RGB PNG tagged sRGB, atomically (see atomic_file.h). Alpha is not written.
// Throws std::invalid_argument for an empty or inconsistent image, std::runtime_error on I/O errors.
void writePng(const std::string& path, const Image& image, const ToneMap& toneMap);

// The same PNG as writePng, in memory (for the browser console's preview).
std::vector<std::uint8_t> encodePng(const Image& image, const ToneMap& toneMap);

// Display-ready 8-bit sRGB pixels (rgb: 3 bytes a pixel, rows top-down), written atomically.
void writePngRgb8(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb);

// Reads a PNG as 8-bit RGBA; each channel holds the ENCODED byte value / 255 (not linear radiance).
// Throws std::runtime_error.
Image readPng8(const std::string& path);

} // namespace aurorawall::io
