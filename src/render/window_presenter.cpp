#include "render/window_presenter.h"

#include "render/hud_font.h"

namespace aurorawall::render {

namespace {

gl::ShaderSource displayShader(const std::string& shaderDir)
{
    gl::ShaderSource source;
    source.modules.push_back(gl::readShaderModule(shaderDir + "/render/tone_map.glsl"));
    source.modules.push_back(gl::readShaderModule(shaderDir + "/render/display.frag"));
    return source;
}

} // namespace

WindowPresenter::WindowPresenter(const std::string& shaderDir, const io::ToneMap& toneMap)
    : program_(gl::Program::graphics(gl::fullScreenTriangleVertexShader(), displayShader(shaderDir)))
{
    program_.set("uExposure", static_cast<float>(toneMap.exposure));
    program_.set("uCurve", io::toneCurveCode(toneMap.curve));
}

void WindowPresenter::setHud(const std::vector<std::string>& lines)
{
    if (lines == hudLines_)
        return;
    hudLines_ = lines;
    hud_.reset();
    if (lines.empty())
        return;
    const HudMask mask = rasterizeHud(lines);
    hud_ = gl::Texture::create2D(mask.width, mask.height, gl::TexelFormat::R32F, gl::Filter::Nearest, gl::Wrap::Clamp);
    hud_->upload(mask.coverage);
}

void WindowPresenter::present(gl::Context& context, int window, const gl::Texture& image,
                              const gl::FullScreenTriangle& triangle, bool withHud)
{
    context.bindWindowFramebuffer(window);
    program_.bindTexture("uTile", 0, image.id());
    const bool hud = withHud && hud_.has_value();
    if (hud)
        program_.bindTexture("uHud", 1, hud_->id());
    program_.set("uHudScale", hud ? (image.height() >= kLargeHudHeightPx ? 2 : 1) : 0);
    program_.use();
    triangle.draw();
}

} // namespace aurorawall::render
