#include "io/png.h"

#include "io/atomic_file.h"

#include <png.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace aurorawall::io {

// Both functions use libpng's simplified API (png_image_*): it reports errors through
// image.message instead of longjmp, and png_image_write_to_file removes a partial file itself.

namespace {

// The image tone mapped and quantised to 8-bit RGB (round(255 v)).
std::vector<std::uint8_t> toneMappedRgb8(const Image& image, const ToneMap& toneMap, const std::string& name)
{
    checkImage(image);
    if (image.width == 0 || image.height == 0)
        throw std::invalid_argument(name + ": cannot write an empty image as PNG");
    std::vector<std::uint8_t> bytes(3 * std::size_t(image.width) * image.height);
    for (std::size_t i = 0; i < bytes.size() / 3; ++i) {
        const float* p = &image.rgba[4 * i];
        const glm::dvec3 display = toneMapPixel(glm::dvec3(p[0], p[1], p[2]), toneMap);
        for (int c = 0; c < 3; ++c)
            bytes[3 * i + c] = std::uint8_t(std::lround(255.0 * display[c]));
    }
    return bytes;
}

png_image rgb8Header(int width, int height)
{
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    png.width = png_uint_32(width);
    png.height = png_uint_32(height);
    png.format = PNG_FORMAT_RGB; // 8-bit, not linear: libpng writes an sRGB chunk
    return png;
}

} // namespace

void writePng(const std::string& path, const Image& image, const ToneMap& toneMap)
{
    writePngRgb8(path, image.width, image.height, toneMappedRgb8(image, toneMap, path));
}

std::vector<std::uint8_t> encodePng(const Image& image, const ToneMap& toneMap)
{
    const std::vector<std::uint8_t> rgb = toneMappedRgb8(image, toneMap, "PNG");
    png_image png = rgb8Header(image.width, image.height);
    png_alloc_size_t size = 0;
    if (!png_image_write_to_memory(&png, nullptr, &size, 0, rgb.data(), 0, nullptr)) // asks the size
        throw std::runtime_error(std::string("cannot encode PNG: ") + png.message);
    std::vector<std::uint8_t> bytes(size);
    if (!png_image_write_to_memory(&png, bytes.data(), &size, 0, rgb.data(), 0, nullptr))
        throw std::runtime_error(std::string("cannot encode PNG: ") + png.message);
    bytes.resize(size);
    return bytes;
}

void writePngRgb8(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb)
{
    if (width <= 0 || height <= 0 || rgb.size() != 3 * std::size_t(width) * std::size_t(height))
        throw std::invalid_argument(path + ": cannot write a PNG of " + std::to_string(rgb.size()) + " bytes as " +
                                    std::to_string(width) + " x " + std::to_string(height) + " RGB");
    writeFileAtomically(path, [&](const std::string& temporary) {
        png_image png = rgb8Header(width, height);
        if (!png_image_write_to_file(&png, temporary.c_str(), 0, rgb.data(), 0, nullptr))
            throw std::runtime_error(path + ": cannot write PNG: " + png.message);
    });
}

Image readPng8(const std::string& path)
{
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&png, path.c_str()))
        throw std::runtime_error(path + ": cannot read PNG: " + png.message);
    png.format = PNG_FORMAT_RGBA;
    std::vector<std::uint8_t> bytes(PNG_IMAGE_SIZE(png));
    if (!png_image_finish_read(&png, nullptr, bytes.data(), 0, nullptr)) {
        png_image_free(&png);
        throw std::runtime_error(path + ": cannot read PNG: " + png.message);
    }
    Image image(int(png.width), int(png.height));
    for (std::size_t i = 0; i < bytes.size(); ++i)
        image.rgba[i] = float(bytes[i]) / 255.0f;
    return image;
}

} // namespace aurorawall::io
