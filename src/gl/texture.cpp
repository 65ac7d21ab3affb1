#include "gl/texture.h"

#include "gl/functions.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace aurorawall::gl {
namespace {

GLenum internalFormat(TexelFormat format)
{
    switch (format) {
    case TexelFormat::R32F: return GL_R32F;
    case TexelFormat::RG32F: return GL_RG32F;
    case TexelFormat::RGB32F: return GL_RGB32F;
    case TexelFormat::RGBA32F: return GL_RGBA32F;
    }
    return GL_RGBA32F;
}

GLenum pixelFormat(TexelFormat format)
{
    switch (format) {
    case TexelFormat::R32F: return GL_RED;
    case TexelFormat::RG32F: return GL_RG;
    case TexelFormat::RGB32F: return GL_RGB;
    case TexelFormat::RGBA32F: return GL_RGBA;
    }
    return GL_RGBA;
}

} // namespace

int channelCount(TexelFormat format)
{
    switch (format) {
    case TexelFormat::R32F: return 1;
    case TexelFormat::RG32F: return 2;
    case TexelFormat::RGB32F: return 3;
    case TexelFormat::RGBA32F: return 4;
    }
    return 4;
}

Texture::Texture(GLenum target, int width, int height, int depth, TexelFormat format, Filter filter, Wrap wrap)
    : target_(target), format_(format), width_(width), height_(height), depth_(depth)
{
    if (width < 1 || height < 1 || depth < 1)
        throw std::invalid_argument("Texture: size must be positive (got " + std::to_string(width) + "x" +
                                    std::to_string(height) + "x" + std::to_string(depth) + ")");
    glCreateTextures(target, 1, &id_);
    const GLenum internal = internalFormat(format);
    if (target == GL_TEXTURE_2D)
        glTextureStorage2D(id_, 1, internal, width, height);
    else
        glTextureStorage3D(id_, 1, internal, width, height, depth);
    const GLint glFilter = filter == Filter::Linear ? GL_LINEAR : GL_NEAREST;
    const GLint glWrap = wrap == Wrap::Repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE;
    glTextureParameteri(id_, GL_TEXTURE_MIN_FILTER, glFilter);
    glTextureParameteri(id_, GL_TEXTURE_MAG_FILTER, glFilter);
    for (GLenum axis : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
        glTextureParameteri(id_, axis, glWrap);
}

Texture Texture::create2D(int width, int height, TexelFormat format, Filter filter, Wrap wrap)
{
    return Texture(GL_TEXTURE_2D, width, height, 1, format, filter, wrap);
}

Texture Texture::create3D(int width, int height, int depth, TexelFormat format, Filter filter, Wrap wrap)
{
    return Texture(GL_TEXTURE_3D, width, height, depth, format, filter, wrap);
}

Texture Texture::create2DArray(int width, int height, int layers, TexelFormat format, Filter filter, Wrap wrap)
{
    return Texture(GL_TEXTURE_2D_ARRAY, width, height, layers, format, filter, wrap);
}

Texture::Texture(Texture&& other) noexcept
    : id_(std::exchange(other.id_, 0)), target_(other.target_), format_(other.format_),
      width_(other.width_), height_(other.height_), depth_(other.depth_)
{
}

Texture& Texture::operator=(Texture&& other) noexcept
{
    std::swap(id_, other.id_);
    target_ = other.target_;
    format_ = other.format_;
    width_ = other.width_;
    height_ = other.height_;
    depth_ = other.depth_;
    return *this;
}

Texture::~Texture()
{
    if (id_)
        glDeleteTextures(1, &id_);
}

void Texture::upload(const std::vector<float>& texels)
{
    const size_t expected = size_t(width_) * size_t(height_) * size_t(depth_) * size_t(channelCount(format_));
    if (texels.size() != expected)
        throw std::invalid_argument("Texture::upload: got " + std::to_string(texels.size()) + " floats, expected " +
                                    std::to_string(expected));
    const GLenum format = pixelFormat(format_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4); // rows of floats are always 4-byte aligned
    if (target_ == GL_TEXTURE_2D)
        glTextureSubImage2D(id_, 0, 0, 0, width_, height_, format, GL_FLOAT, texels.data());
    else
        glTextureSubImage3D(id_, 0, 0, 0, 0, width_, height_, depth_, format, GL_FLOAT, texels.data());
}

} // namespace aurorawall::gl
