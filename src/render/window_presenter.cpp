#include "render/window_presenter.h"

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

void WindowPresenter::present(gl::Context& context, int window, const gl::FloatTarget& tile,
                              const gl::FullScreenTriangle& triangle)
{
    context.bindWindowFramebuffer(window);
    program_.bindTexture("uTile", 0, tile.texture().id());
    program_.use();
    triangle.draw();
}

} // namespace aurorawall::render
