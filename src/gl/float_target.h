#pragma once
// A framebuffer with one GL_RGBA32F colour texture: where a tile is rendered before readback.
// Framebuffers are not shared between contexts: create it with the context that draws into it.
#include "gl/texture.h"

#include <vector>

namespace aurorawall::gl {

class FloatTarget {
public:
    FloatTarget(int width, int height);
    FloatTarget(FloatTarget&& other) noexcept;
    FloatTarget& operator=(FloatTarget&& other) noexcept;
    ~FloatTarget();

    // Binds it for drawing and reading, with the viewport covering it.
    void bind() const;

    // RGBA floats in GL's row order, bottom-up: pixel (x, y) starts at 4 * (y * width + x), and
    // y = 0 is the bottom row (gl_FragCoord.y = 0.5). Waits for rendering to finish.
    std::vector<float> readback() const;

    // Copies the whole image, scaled with linear filtering, into the framebuffer `destination`
    // (0: the bound window's) over the rectangle (0, 0, width, height).
    void blitTo(GLuint destination, int width, int height) const;

    int width() const { return texture_.width(); }
    int height() const { return texture_.height(); }
    GLuint framebuffer() const { return framebuffer_; }
    const Texture& texture() const { return texture_; }
    Texture& texture() { return texture_; } // e.g. to upload pixels rendered elsewhere

private:
    Texture texture_;
    GLuint framebuffer_ = 0;
};

} // namespace aurorawall::gl
