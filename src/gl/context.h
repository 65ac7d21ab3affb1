#pragma once
// An OpenGL 4.5 core context from one of the backends, with the GL functions loaded.
//
// Headless backends (EGL, OSMesa) have no windows: render into your own framebuffers (FloatTarget).
// GLFW opens one window per WindowSpec; each window has its own context, and the contexts of
// windows after the first share objects with the first one. Shared are textures, buffers, shaders
// and programs; NOT shared are container objects (framebuffers, vertex arrays, queries), so create
// those per window after makeCurrent(i).
//
// Creating a context leaves it current (window 0) and prints nothing.
#include "gl/backend.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace aurorawall::gl {

// The keys a window reports: the letters A to Z by their upper-case ASCII codes, and these.
enum Key : std::int32_t {
    KeyUp = 256,
    KeyDown,
    KeyLeft,
    KeyRight,
    KeyPlus,  // '+' or '=' on the main keyboard, '+' on the keypad
    KeyMinus, // '-' on either
};

// What an operator did in a window since the last takeInputEvents().
struct InputEvent {
    enum Type : std::int32_t {
        KeyPressed = 1, // `key` went down, or repeats while held
        Dragged = 2,    // the pointer moved by (dx, dy) window pixels with the left button held
    };
    std::int32_t type = KeyPressed;
    std::int32_t key = 0; // a Key
    double dx = 0.0, dy = 0.0; // x to the right, y down
};

// A gamepad's state in GLFW's standard gamepad layout (GLFWgamepadstate, the SDL game controller
// mapping): sticks' axes in [-1, 1] with +y down, triggers' axes -1 released to +1 fully pressed;
// buttons 1 while held.
struct GamepadState {
    enum Axis { LeftX, LeftY, RightX, RightY, LeftTrigger, RightTrigger, AxisCount };
    enum Button { A, B, X, Y, LeftBumper, RightBumper, Back, Start, Guide, LeftThumb, RightThumb,
                  DpadUp, DpadRight, DpadDown, DpadLeft, ButtonCount };
    float axes[AxisCount] = {0.0f, 0.0f, 0.0f, 0.0f, -1.0f, -1.0f};
    unsigned char buttons[ButtonCount] = {};
};

// One window of the GLFW backend, in screen pixels.
struct WindowSpec {
    std::string title;
    int widthPx = 0, heightPx = 0;
    int x = -1, y = -1;      // desktop position of the top-left corner; -1: let the system choose
    int monitor = -1;        // fullscreen on this monitor (index into glfwGetMonitors)
    bool fullscreen = false; // needs monitor >= 0
};

class Context {
public:
    virtual ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    // Makes the context of `window` current (headless: the only context, window must be 0) and
    // loads the GL functions for it.
    virtual void makeCurrent(int window = 0) = 0;

    virtual int windowCount() const { return 0; }
    // Makes window i current and binds its default framebuffer, viewport covering it.
    virtual void bindWindowFramebuffer(int window);
    virtual void swapBuffers(int window);
    virtual void pollEvents() {}
    // A window was closed or Esc was pressed in one.
    virtual bool closeRequested() const { return false; }
    // The key presses and drags in this context's windows that pollEvents() saw since the last
    // call, oldest first (consecutive drags merged into one), at most `maxEvents`: later ones are
    // dropped. Headless: none.
    virtual std::vector<InputEvent> takeInputEvents(std::size_t /*maxEvents*/) { return {}; }
    // The first connected gamepad's state now, or false if there is none (headless: never).
    virtual bool gamepad(GamepadState& /*state*/) const { return false; }

    // GL_RENDERER and GL_VERSION of the current context, for logs (e.g. "llvmpipe (LLVM 15.0.6, 256 bits)").
    std::string vendorName() const; // GL_VENDOR, e.g. "NVIDIA Corporation" or "Mesa"
    std::string rendererName() const;
    std::string glVersion() const;

protected:
    Context() = default;
};

// GL_RENDERER of the current context (e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"); empty without one.
std::string currentRendererName();

// Whether the current context has the GL extension `name` (e.g. "GL_ARB_shader_clock").
bool hasExtension(const std::string& name);

// The largest width and height, in pixels, of a render target of the current context (a texture
// attached to a framebuffer, drawn through the viewport): the least of GL_MAX_TEXTURE_SIZE,
// GL_MAX_RENDERBUFFER_SIZE and either of GL_MAX_VIEWPORT_DIMS (16384 each on llvmpipe).
int largestRenderTargetPx();

// True for Mesa's CPU renderers (llvmpipe, softpipe), by their GL_RENDERER.
bool isSoftwareRenderer(const std::string& rendererName);

// Throws std::runtime_error with one line saying why when no context can be made.
// windowsForGlfw is used by Backend::Glfw only (at least one window).
// EGL tries the device platform (device $AURORAWALL_EGL_DEVICE only, if set; else the hardware devices
// from the one numbered nodeRank, the rank's index among its node's ranks, round, then the software
// ones: gl/device_order.h), then the surfaceless platform, then the default display.
std::unique_ptr<Context> createContext(Backend backend, const std::vector<WindowSpec>& windowsForGlfw = {},
                                       int nodeRank = 0);

} // namespace aurorawall::gl
