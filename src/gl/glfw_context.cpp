// GLFW windows, one context per window; windows after the first share the first one's objects.
// GLFW loads libGL itself at run time, so nothing here links it.
#include "gl/backends.h"
#include "gl/functions.h"
#include "gl/loader.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <stdexcept>
#include <string>

namespace aurorawall::gl {
namespace {

static_assert(GamepadState::AxisCount == GLFW_GAMEPAD_AXIS_LAST + 1 &&
                  GamepadState::ButtonCount == GLFW_GAMEPAD_BUTTON_LAST + 1 &&
                  GamepadState::RightTrigger == GLFW_GAMEPAD_AXIS_RIGHT_TRIGGER &&
                  GamepadState::DpadLeft == GLFW_GAMEPAD_BUTTON_DPAD_LEFT,
              "GamepadState has GLFW's gamepad layout");

std::string lastGlfwError;

void recordGlfwError(int, const char* description) { lastGlfwError = description; }

void* glfwProcAddress(const char* name)
{
    return reinterpret_cast<void*>(glfwGetProcAddress(name));
}

// The Key of a GLFW key code, or 0 for a key the wall does not report.
std::int32_t keyOf(int glfwKey)
{
    if (glfwKey >= GLFW_KEY_A && glfwKey <= GLFW_KEY_Z) // GLFW's letter codes are their ASCII codes
        return glfwKey;
    switch (glfwKey) {
    case GLFW_KEY_UP: return KeyUp;
    case GLFW_KEY_DOWN: return KeyDown;
    case GLFW_KEY_LEFT: return KeyLeft;
    case GLFW_KEY_RIGHT: return KeyRight;
    case GLFW_KEY_EQUAL:
    case GLFW_KEY_KP_ADD: return KeyPlus;
    case GLFW_KEY_MINUS:
    case GLFW_KEY_KP_SUBTRACT: return KeyMinus;
    default: return 0;
    }
}

class GlfwContext : public Context {
public:
    // glfwInit/glfwTerminate are process-wide: the first live GlfwContext initializes, the last ends.
    GlfwContext()
    {
        if (liveContexts_ == 0) {
            glfwSetErrorCallback(recordGlfwError);
            if (!glfwInit())
                throw std::runtime_error("GLFW: glfwInit failed (" + lastGlfwError + ")");
        }
        ++liveContexts_;
    }

    ~GlfwContext() override
    {
        for (GLFWwindow* w : windows_)
            glfwDestroyWindow(w);
        if (--liveContexts_ == 0) {
            glfwTerminate();
            forgetFunctions();
        }
    }

    void openWindow(const WindowSpec& spec)
    {
        const std::string name = "GLFW: window '" + spec.title + "'";
        GLFWmonitor* monitor = nullptr;
        if (spec.fullscreen) {
            int count = 0;
            GLFWmonitor** monitors = glfwGetMonitors(&count);
            if (spec.monitor < 0 || spec.monitor >= count)
                throw std::runtime_error(name + ": fullscreen on monitor " + std::to_string(spec.monitor) +
                                         " but there are " + std::to_string(count) + " monitors");
            monitor = monitors[spec.monitor];
        }
        glfwDefaultWindowHints();
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE); // shown once placed
        GLFWwindow* share = windows_.empty() ? nullptr : windows_.front();
        GLFWwindow* window = glfwCreateWindow(spec.widthPx, spec.heightPx, spec.title.c_str(), monitor, share);
        if (!window)
            throw std::runtime_error(name + ": no OpenGL 4.5 core window (" + lastGlfwError + ")");
        windows_.push_back(window);
        glfwSetWindowUserPointer(window, this);
        glfwSetKeyCallback(window, onKey);
        glfwSetMouseButtonCallback(window, onMouseButton);
        glfwSetCursorPosCallback(window, onCursor);
        if (!monitor && spec.x >= 0 && spec.y >= 0)
            glfwSetWindowPos(window, spec.x, spec.y);
        glfwShowWindow(window);
        glfwMakeContextCurrent(window);
        glfwSwapInterval(0); // several windows swap in turn; vsync would wait once per window
    }

    void makeCurrent(int window) override
    {
        glfwMakeContextCurrent(windows_.at(window));
        loadFunctions(glfwProcAddress);
    }

    int windowCount() const override { return static_cast<int>(windows_.size()); }

    void bindWindowFramebuffer(int window) override
    {
        makeCurrent(window);
        int width = 0, height = 0;
        glfwGetFramebufferSize(windows_.at(window), &width, &height);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, width, height);
    }

    void swapBuffers(int window) override { glfwSwapBuffers(windows_.at(window)); }

    void pollEvents() override { glfwPollEvents(); }

    bool closeRequested() const override
    {
        for (GLFWwindow* w : windows_)
            if (glfwWindowShouldClose(w))
                return true;
        return false;
    }

    std::vector<InputEvent> takeInputEvents(std::size_t maxEvents) override
    {
        std::vector<InputEvent> events;
        events.swap(events_);
        if (events.size() > maxEvents)
            events.resize(maxEvents);
        return events;
    }

    bool gamepad(GamepadState& state) const override
    {
        for (int joystick = GLFW_JOYSTICK_1; joystick <= GLFW_JOYSTICK_LAST; ++joystick) {
            GLFWgamepadstate glfw;
            if (!glfwJoystickIsGamepad(joystick) || !glfwGetGamepadState(joystick, &glfw))
                continue;
            std::copy(std::begin(glfw.axes), std::end(glfw.axes), state.axes);
            std::copy(std::begin(glfw.buttons), std::end(glfw.buttons), state.buttons);
            return true;
        }
        return false;
    }

private:
    static GlfwContext& of(GLFWwindow* window) { return *static_cast<GlfwContext*>(glfwGetWindowUserPointer(window)); }

    // Esc asks to close; other keys are recorded as pressed, also while they repeat.
    static void onKey(GLFWwindow* window, int glfwKey, int, int action, int)
    {
        if (glfwKey == GLFW_KEY_ESCAPE && action == GLFW_PRESS)
            glfwSetWindowShouldClose(window, GLFW_TRUE);
        const std::int32_t key = keyOf(glfwKey);
        if (key != 0 && (action == GLFW_PRESS || action == GLFW_REPEAT))
            of(window).events_.push_back({InputEvent::KeyPressed, key, 0.0, 0.0});
    }

    static void onMouseButton(GLFWwindow* window, int button, int action, int)
    {
        if (button != GLFW_MOUSE_BUTTON_LEFT)
            return;
        GlfwContext& context = of(window);
        context.dragging_ = action == GLFW_PRESS;
        // The drag starts where the last motion event left the pointer: asking the server now would
        // give where it is after motions still queued, which would then be lost.
        if (context.cursorWindow_ != window) {
            glfwGetCursorPos(window, &context.cursorX_, &context.cursorY_);
            context.cursorWindow_ = window;
        }
    }

    static void onCursor(GLFWwindow* window, double x, double y)
    {
        GlfwContext& context = of(window);
        if (context.dragging_ && context.cursorWindow_ == window) {
            std::vector<InputEvent>& events = context.events_;
            if (events.empty() || events.back().type != InputEvent::Dragged)
                events.push_back({InputEvent::Dragged, 0, 0.0, 0.0});
            events.back().dx += x - context.cursorX_;
            events.back().dy += y - context.cursorY_;
        }
        context.cursorX_ = x;
        context.cursorY_ = y;
        context.cursorWindow_ = window;
    }

    static inline int liveContexts_ = 0;
    std::vector<GLFWwindow*> windows_;
    std::vector<InputEvent> events_; // since the last takeInputEvents
    bool dragging_ = false;          // the left button is held in one of the windows
    double cursorX_ = 0.0, cursorY_ = 0.0; // the pointer in cursorWindow_, window pixels
    GLFWwindow* cursorWindow_ = nullptr;
};

} // namespace

std::unique_ptr<Context> createGlfwContext(const std::vector<WindowSpec>& windows)
{
    if (windows.empty())
        throw std::runtime_error("GLFW: no windows asked for");
    auto context = std::make_unique<GlfwContext>();
    for (const WindowSpec& spec : windows)
        context->openWindow(spec);
    context->makeCurrent(0);
    return context;
}

} // namespace aurorawall::gl
