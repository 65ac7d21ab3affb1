#include "gl/float_target.h"

#include "gl/functions.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace aurorawall::gl {

FloatTarget::FloatTarget(int width, int height)
    : texture_(Texture::create2D(width, height, TexelFormat::RGBA32F, Filter::Nearest, Wrap::Clamp)),
      work_(Texture::create2D(width, height, TexelFormat::R32F, Filter::Nearest, Wrap::Clamp))
{
    glCreateFramebuffers(1, &framebuffer_);
    glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT0, texture_.id(), 0);
    glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT1, work_.id(), 0);
    const GLenum drawBuffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(framebuffer_, 2, drawBuffers);
    glNamedFramebufferReadBuffer(framebuffer_, GL_COLOR_ATTACHMENT0);
    const GLenum status = glCheckNamedFramebufferStatus(framebuffer_, GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        glDeleteFramebuffers(1, &framebuffer_);
        throw std::runtime_error("FloatTarget: RGBA32F + R32F framebuffer incomplete (status " +
                                 std::to_string(status) + ")");
    }
}

FloatTarget::FloatTarget(FloatTarget&& other) noexcept
    : texture_(std::move(other.texture_)), work_(std::move(other.work_)),
      framebuffer_(std::exchange(other.framebuffer_, 0))
{
}

FloatTarget& FloatTarget::operator=(FloatTarget&& other) noexcept
{
    std::swap(texture_, other.texture_);
    std::swap(work_, other.work_);
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

void FloatTarget::checkRows(int firstRow, int rows) const
{
    if (firstRow < 0 || rows < 1 || firstRow + rows > height())
        throw std::invalid_argument("FloatTarget: rows [" + std::to_string(firstRow) + ", " +
                                    std::to_string(firstRow + rows) + ") outside a target of " +
                                    std::to_string(height()) + " rows");
}

std::vector<float> FloatTarget::readback() const
{
    std::vector<float> pixels(size_t(width()) * size_t(height()) * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width(), height(), GL_RGBA, GL_FLOAT, pixels.data());
    return pixels;
}

std::vector<float> FloatTarget::readbackRgb(int firstRow, int rows) const
{
    checkRows(firstRow, rows);
    std::vector<float> pixels(size_t(width()) * size_t(rows) * 3);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, firstRow, width(), rows, GL_RGB, GL_FLOAT, pixels.data());
    return pixels;
}

std::vector<float> FloatTarget::readbackWork(int firstRow, int rows) const
{
    checkRows(firstRow, rows);
    std::vector<float> work(size_t(width()) * size_t(rows));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
    glNamedFramebufferReadBuffer(framebuffer_, GL_COLOR_ATTACHMENT1);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, firstRow, width(), rows, GL_RED, GL_FLOAT, work.data());
    glNamedFramebufferReadBuffer(framebuffer_, GL_COLOR_ATTACHMENT0);
    return work;
}

void FloatTarget::uploadRgbHalf(int firstRow, int rows, const std::vector<std::uint16_t>& rgb)
{
    checkRows(firstRow, rows);
    if (rgb.size() != size_t(width()) * size_t(rows) * 3)
        throw std::invalid_argument("FloatTarget: " + std::to_string(rgb.size()) + " halves for " +
                                    std::to_string(rows) + " rows of " + std::to_string(width()) + " RGB pixels");
    glPixelStorei(GL_UNPACK_ALIGNMENT, 2); // rows of 6 * width bytes
    glTextureSubImage2D(texture_.id(), 0, 0, firstRow, width(), rows, GL_RGB, GL_HALF_FLOAT, rgb.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
}

void FloatTarget::blitTo(GLuint destination, int width, int height) const
{
    glBlitNamedFramebuffer(framebuffer_, destination, 0, 0, this->width(), this->height(), 0, 0, width, height,
                           GL_COLOR_BUFFER_BIT, GL_LINEAR);
}

} // namespace aurorawall::gl
