#pragma once
// Puts rendered tiles on screen (GLFW backend): draws the float tile through the same tone
// curve as the PNG preview into the window's back buffer. The swap happens after the swap
// barrier, so all screens of the wall flip together.
#include "gl/context.h"
#include "gl/float_target.h"
#include "gl/full_screen_triangle.h"
#include "gl/shader_program.h"
#include "io/tone_map.h"

#include <string>

namespace aurorawall::render {

class WindowPresenter {
public:
    WindowPresenter(const std::string& shaderDir, const io::ToneMap& toneMap);

    void present(gl::Context& context, int window, const gl::FloatTarget& tile, const gl::FullScreenTriangle& triangle);

private:
    gl::Program program_;
};

} // namespace aurorawall::render
