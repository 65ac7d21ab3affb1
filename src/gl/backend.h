#pragma once
// Which library gives us an OpenGL 4.5 core context.
#include <string>

namespace aurorawall::gl {

enum class Backend {
    Egl,    // headless, EGL device or surfaceless platform; the default (works on NVIDIA too)
    Osmesa, // headless, Mesa's off-screen library (removed upstream in Mesa 25.1)
    Glfw,   // one window per screen, on an X display
};

// "egl", "osmesa" or "glfw"; throws aurorawall::InputError naming --backend otherwise.
Backend parseBackend(const std::string& name);

std::string backendName(Backend backend);

} // namespace aurorawall::gl
