#pragma once
// Which library gives us an OpenGL 4.5 core context.
#include <string>

namespace aurorawall::gl {

enum class Backend {
    Egl,    // headless, EGL device or surfaceless platform; the default (works on NVIDIA too)
    Osmesa, // headless, Mesa's off-screen library (removed upstream in Mesa 25.1)
    Glfw,   // one window per screen, on an X display
};

// "egl", "osmesa" or "glfw" (the words of --backend, parsed by src/app/render_options.cpp).
std::string backendName(Backend backend);

} // namespace aurorawall::gl
