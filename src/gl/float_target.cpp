#include "gl/float_target.h"

#include "gl/functions.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace aurorawall::gl {

FloatTarget::FloatTarget(int width, int height)
    : texture_(Texture::create2D(width, height, TexelFormat::RGBA32F, Filter::Nearest, Wrap::Clamp))
{
    glCreateFramebuffers(1, &framebuffer_);
    glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT0, texture_.id(), 0);
    const GLenum status = glCheckNamedFramebufferStatus(framebuffer_, GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        glDeleteFramebuffers(1, &framebuffer_);
        throw std::runtime_error("FloatTarget: RGBA32F framebuffer incomplete (status " + std::to_string(status) + ")");
    }
}

FloatTarget::FloatTarget(FloatTarget&& other) noexcept
    : texture_(std::move(other.texture_)), framebuffer_(std::exchange(other.framebuffer_, 0))
{
}

FloatTarget& FloatTarget::operator=(FloatTarget&& other) noexcept
{
    std::swap(texture_, other.texture_);
    std::swap(framebuffer_, other.framebuffer_);
    return *this;
}

FloatTarget::~FloatTarget()
{
    if (framebuffer_)
        glDeleteFramebuffers(1, &framebuffer_);
}

void FloatTarget::bind() const
{
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glViewport(0, 0, width(), height());
}

std::vector<float> FloatTarget::readback() const
{
    std::vector<float> pixels(size_t(width()) * size_t(height()) * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width(), height(), GL_RGBA, GL_FLOAT, pixels.data());
    return pixels;
}

void FloatTarget::blitTo(GLuint destination, int width, int height) const
{
    glBlitNamedFramebuffer(framebuffer_, destination, 0, 0, this->width(), this->height(), 0, 0, width, height,
                           GL_COLOR_BUFFER_BIT, GL_LINEAR);
}

} // namespace aurorawall::gl
