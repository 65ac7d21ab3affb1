#pragma once
// A framebuffer where the raymarcher draws a tile, with two float colour textures:
//   attachment 0, GL_RGBA32F: the radiance (linear RGB in the scene's radiance unit), alpha 1;
//   attachment 1, GL_R32F: the ray's work, 1 + its aurora samples (shaders/render/pixel.glsl), with
//   which the load balancer shares a draw's measured time among the bands it covered.
// A shader that writes only location 0 leaves attachment 1 undefined.
// Rows are GL's, bottom-up: row 0 is the bottom one (gl_FragCoord.y = 0.5).
// The compute march writes the same two textures as images instead (render/tile_renderer.h).
// Framebuffers are not shared between contexts: create it with the context that draws into it.
#include "gl/texture.h"

#include <cstdint>
#include <vector>

namespace aurorawall::gl {

class FloatTarget {
public:
    FloatTarget(int width, int height);
    FloatTarget(FloatTarget&& other) noexcept;
    FloatTarget& operator=(FloatTarget&& other) noexcept;
    ~FloatTarget();

    // Binds it for drawing (both attachments) and reading, with the viewport covering it.
    void bind() const;

    // The radiance, RGBA floats: pixel (x, y) starts at 4 * (y * width + x). Waits for rendering.
    std::vector<float> readback() const;

    // The radiance of rows [firstRow, firstRow + rows), RGB floats: pixel (x, firstRow + j) starts at
    // 3 * (j * width + x). Waits for rendering. Throws std::invalid_argument for rows outside the target.
    std::vector<float> readbackRgb(int firstRow, int rows) const;

    // The work of rows [firstRow, firstRow + rows), one float a pixel in the same order.
    std::vector<float> readbackWork(int firstRow, int rows) const;

    // Replaces the radiance of rows [firstRow, firstRow + rows) with RGB half floats (IEEE binary16
    // bits, io/half_pixels.h, in readbackRgb's order) and alpha 1; the conversion to float is exact.
    // Throws std::invalid_argument for rows outside the target or a size other than 3 * width * rows.
    void uploadRgbHalf(int firstRow, int rows, const std::vector<std::uint16_t>& rgb);

    // Copies the whole radiance, scaled with linear filtering, into the framebuffer `destination`
    // (0: the bound window's) over the rectangle (0, 0, width, height).
    void blitTo(GLuint destination, int width, int height) const;

    int width() const { return texture_.width(); }
    int height() const { return texture_.height(); }
    GLuint framebuffer() const { return framebuffer_; }
    const Texture& texture() const { return texture_; } // the radiance
    const Texture& work() const { return work_; }

private:
    void checkRows(int firstRow, int rows) const;

    Texture texture_;
    Texture work_;
    GLuint framebuffer_ = 0;
};

} // namespace aurorawall::gl
