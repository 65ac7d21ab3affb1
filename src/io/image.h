#pragma once
// An RGBA float image in memory, and the operations that assemble a wall from tiles.
#include <cstddef>
#include <vector>

namespace aurorawall::io {

struct Image {
    int width = 0, height = 0;
    std::vector<float> rgba; // linear radiance, 4 floats per pixel, rows TOP-DOWN

    Image() = default;
    Image(int width, int height); // all zeros: black, alpha 0

    float* pixel(int x, int y) { return &rgba[4 * (std::size_t(y) * width + x)]; }
    const float* pixel(int x, int y) const { return &rgba[4 * (std::size_t(y) * width + x)]; }
};

// Throws std::invalid_argument unless width, height >= 0 and rgba holds 4 * width * height floats.
void checkImage(const Image& image);

// An image from a glReadPixels(GL_RGBA, GL_FLOAT) buffer, whose rows run BOTTOM-UP (GL convention).
Image imageFromGlReadback(int width, int height, const std::vector<float>& bottomUpRgba);

// Copies `tile` into `wall` with the tile's top-left pixel at (x, y) of the wall (top-down rows).
// Throws std::invalid_argument if the tile does not fit inside the wall.
void pasteTile(Image& wall, const Image& tile, int x, int y);

// The w x h rectangle whose top-left pixel is (x, y). Throws std::invalid_argument if it leaves the image.
Image crop(const Image& image, int x, int y, int w, int h);

// Number of NaN or infinite floats (all four channels).
std::size_t countNonFinite(const Image& image);

// Differences over all four channels of two images of equal size (std::invalid_argument otherwise).
// A non-finite difference (NaN or inf in either image) counts as +inf.
struct ImageDifference {
    double maxAbs = 0;      // max |a - b|
    double maxRelative = 0; // maxAbs / max |reference|; 0 if both are 0, inf if only maxAbs is not
    double rms = 0;         // sqrt(mean (a - b)^2)
};
ImageDifference compareImages(const Image& reference, const Image& other);

} // namespace aurorawall::io
