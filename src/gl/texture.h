#pragma once
// Float textures (2D, 3D, 2D arrays) for lookup tables and render targets, owned (move-only).
#include <GL/glcorearb.h>

#include <vector>

namespace aurorawall::gl {

enum class TexelFormat { R32F, RG32F, RGB32F, RGBA32F };
enum class Filter { Nearest, Linear };
enum class Wrap { Clamp, Repeat }; // Clamp: GL_CLAMP_TO_EDGE

int channelCount(TexelFormat format);

class Texture {
public:
    static Texture create2D(int width, int height, TexelFormat format, Filter filter, Wrap wrap);
    static Texture create3D(int width, int height, int depth, TexelFormat format, Filter filter, Wrap wrap);
    // depth layers of width x height texels, filtered within a layer only.
    static Texture create2DArray(int width, int height, int layers, TexelFormat format, Filter filter, Wrap wrap);

    Texture(Texture&& other) noexcept;
    Texture& operator=(Texture&& other) noexcept;
    ~Texture();

    // Replaces every texel: channelCount(format) floats per texel, x fastest, then y, then z
    // (y = 0 is the bottom row when sampled at t = 0). Throws std::invalid_argument on a size mismatch.
    void upload(const std::vector<float>& texels);

    GLuint id() const { return id_; }
    GLenum target() const { return target_; }
    TexelFormat format() const { return format_; }
    int width() const { return width_; }
    int height() const { return height_; }
    int depth() const { return depth_; }

private:
    Texture(GLenum target, int width, int height, int depth, TexelFormat format, Filter filter, Wrap wrap);

    GLuint id_ = 0;
    GLenum target_ = 0;
    TexelFormat format_ = TexelFormat::RGBA32F;
    int width_ = 0, height_ = 0, depth_ = 0;
};

} // namespace aurorawall::gl
