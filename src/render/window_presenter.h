#pragma once
// Puts rendered tiles on screen (GLFW backend): draws the float tile through the same tone
// curve as the PNG preview into the window's back buffer, with the heads-up display over it where
// asked. The swap happens after the swap barrier, so all screens of the wall flip together. Only
// the window is drawn on: the tile, which every file output reads, never holds the HUD.
#include "gl/context.h"
#include "gl/float_target.h"
#include "gl/full_screen_triangle.h"
#include "gl/shader_program.h"
#include "gl/texture.h"
#include "io/tone_map.h"

#include <optional>
#include <string>
#include <vector>

namespace aurorawall::render {

class WindowPresenter {
public:
    WindowPresenter(const std::string& shaderDir, const io::ToneMap& toneMap);

    // The HUD's lines (render/hud_font.h); none: no HUD. Uploads a texture: call it with the first
    // window's context current.
    void setHud(const std::vector<std::string>& lines);

    // Draws `image` (a float texture of the window's size: a screen's tile, or the console's
    // preview) into the window. withHud: the HUD (if there are lines) in its top-left corner, at 2
    // window pixels a font pixel on images at least kLargeHudHeightPx high, else at 1.
    void present(gl::Context& context, int window, const gl::Texture& image, const gl::FullScreenTriangle& triangle,
                 bool withHud = false);

    static constexpr int kLargeHudHeightPx = 600;

private:
    gl::Program program_;
    std::vector<std::string> hudLines_;
    std::optional<gl::Texture> hud_; // the mask of hudLines_
};

} // namespace aurorawall::render
