#include "io/image.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace aurorawall::io {

namespace {

std::string sizeText(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

void checkRectangle(const Image& image, int x, int y, int w, int h, const char* what)
{
    if (x < 0 || y < 0 || w < 0 || h < 0 || x + w > image.width || y + h > image.height)
        throw std::invalid_argument(std::string(what) + ": rectangle " + sizeText(w, h) + " at (" +
                                    std::to_string(x) + ", " + std::to_string(y) + ") leaves the " +
                                    sizeText(image.width, image.height) + " image");
}

} // namespace

Image::Image(int width, int height) : width(width), height(height)
{
    if (width < 0 || height < 0)
        throw std::invalid_argument("image size " + sizeText(width, height) + " is negative");
    rgba.assign(4 * std::size_t(width) * height, 0.0f);
}

void checkImage(const Image& image)
{
    if (image.width < 0 || image.height < 0 ||
        image.rgba.size() != 4 * std::size_t(image.width) * image.height)
        throw std::invalid_argument("image " + sizeText(image.width, image.height) + " holds " +
                                    std::to_string(image.rgba.size()) + " floats");
}

Image imageFromGlReadback(int width, int height, const std::vector<float>& bottomUpRgba)
{
    Image image(width, height);
    if (bottomUpRgba.size() != image.rgba.size())
        throw std::invalid_argument("GL readback of " + std::to_string(bottomUpRgba.size()) +
                                    " floats for a " + sizeText(width, height) + " image");
    const std::size_t rowFloats = 4 * std::size_t(width);
    for (int y = 0; y < height; ++y) {
        auto source = bottomUpRgba.begin() + (height - 1 - y) * rowFloats;
        std::copy(source, source + rowFloats, image.pixel(0, y));
    }
    return image;
}

void pasteTile(Image& wall, const Image& tile, int x, int y)
{
    checkImage(wall);
    checkImage(tile);
    checkRectangle(wall, x, y, tile.width, tile.height, "pasteTile");
    for (int row = 0; row < tile.height; ++row)
        std::copy(tile.pixel(0, row), tile.pixel(0, row) + 4 * tile.width, wall.pixel(x, y + row));
}

Image crop(const Image& image, int x, int y, int w, int h)
{
    checkImage(image);
    checkRectangle(image, x, y, w, h, "crop");
    Image result(w, h);
    for (int row = 0; row < h; ++row)
        std::copy(image.pixel(x, y + row), image.pixel(x, y + row) + 4 * w, result.pixel(0, row));
    return result;
}

std::size_t countNonFinite(const Image& image)
{
    return std::count_if(image.rgba.begin(), image.rgba.end(), [](float v) { return !std::isfinite(v); });
}

ImageDifference compareImages(const Image& reference, const Image& other)
{
    checkImage(reference);
    checkImage(other);
    if (reference.width != other.width || reference.height != other.height)
        throw std::invalid_argument("compareImages: sizes differ (" + sizeText(reference.width, reference.height) +
                                    " and " + sizeText(other.width, other.height) + ")");
    const double inf = std::numeric_limits<double>::infinity();
    ImageDifference result;
    double referenceMax = 0, sumSquares = 0;
    for (std::size_t i = 0; i < reference.rgba.size(); ++i) {
        double d = std::abs(double(reference.rgba[i]) - double(other.rgba[i]));
        if (!std::isfinite(d))
            d = inf;
        result.maxAbs = std::max(result.maxAbs, d);
        sumSquares += d * d;
        referenceMax = std::max(referenceMax, std::abs(double(reference.rgba[i])));
    }
    if (!reference.rgba.empty())
        result.rms = std::sqrt(sumSquares / double(reference.rgba.size()));
    if (result.maxAbs > 0)
        result.maxRelative = referenceMax > 0 && result.maxAbs < inf ? result.maxAbs / referenceMax : inf;
    return result;
}

} // namespace aurorawall::io
