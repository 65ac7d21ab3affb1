#pragma once
// One screen this rank shows: the float target its pixels are drawn or uploaded into, and the window
// (context) that target belongs to. Windows present from the target.
#include "gl/float_target.h"
#include "gl/full_screen_triangle.h"
#include "gl/gpu_timer.h"

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace aurorawall::app {

struct ScreenTarget {
    int screen = 0; // index into wall.screens
    int window = 0; // context/window it belongs to (glfw: one per screen; headless: 0)
    std::unique_ptr<gl::FloatTarget> target;     // the screen's size
    std::unique_ptr<gl::FullScreenTriangle> triangle; // vertex arrays belong to one context
    std::unique_ptr<gl::GpuTimer> drawTimer;          // so do timer queries
};

// The target of wall screen `screen` among this rank's; std::logic_error if this rank does not show it.
inline ScreenTarget& screenTarget(std::vector<ScreenTarget>& screens, int screen)
{
    for (ScreenTarget& s : screens)
        if (s.screen == screen)
            return s;
    throw std::logic_error("screen " + std::to_string(screen) + " is not shown by this rank");
}

} // namespace aurorawall::app
