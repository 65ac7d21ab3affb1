// Headless EGL: desktop OpenGL 4.5 core, made current without a surface.
#include "gl/backends.h"
#include "gl/device_order.h"
#include "gl/loader.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace aurorawall::gl {
namespace {

void* eglProcAddress(const char* name)
{
    return reinterpret_cast<void*>(eglGetProcAddress(name));
}

// Whether the space-separated extension list names `extension`.
bool listsExtension(const char* list, const char* extension)
{
    if (!list)
        return false;
    const size_t n = std::strlen(extension);
    for (const char* p = list; (p = std::strstr(p, extension)); p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0'))
            return true;
    return false;
}

bool hasExtension(EGLDisplay display, const char* extension)
{
    return listsExtension(eglQueryString(display, EGL_EXTENSIONS), extension);
}

std::string errorName(EGLint error)
{
    switch (error) {
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    default: return "EGL error " + std::to_string(error);
    }
}

class EglContext : public Context {
public:
    EglContext(EGLDisplay display, EGLContext context) : display_(display), context_(context) {}

    // eglTerminate is not called: EGLDisplay handles are shared per device, so terminating one
    // would end every other context on it. Mesa and NVIDIA clean up at exit.
    ~EglContext() override
    {
        if (eglGetCurrentContext() == context_)
            eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, context_);
    }

    void makeCurrent(int window) override
    {
        if (window != 0)
            throw std::logic_error("EGL: headless context has no window " + std::to_string(window));
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            throw std::runtime_error("EGL: eglMakeCurrent failed (" + errorName(eglGetError()) + ")");
        loadFunctions(eglProcAddress);
    }

private:
    EGLDisplay display_;
    EGLContext context_;
};

// An OpenGL 4.5 core context on `display`, or EGL_NO_CONTEXT with the reason in `why`.
EGLContext createCoreContext(EGLDisplay display, std::string& why)
{
    EGLint major = 0, minor = 0;
    if (display == EGL_NO_DISPLAY) {
        why = "no display";
        return EGL_NO_CONTEXT;
    }
    if (!eglInitialize(display, &major, &minor)) {
        why = "eglInitialize failed (" + errorName(eglGetError()) + ")";
        return EGL_NO_CONTEXT;
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
        why = "no desktop OpenGL API";
        return EGL_NO_CONTEXT;
    }
    if (!hasExtension(display, "EGL_KHR_create_context") ||
        !hasExtension(display, "EGL_KHR_surfaceless_context")) {
        why = "lacks EGL_KHR_create_context or EGL_KHR_surfaceless_context";
        return EGL_NO_CONTEXT;
    }
    // A config is only needed for surfaces; we never make one, so go config-less where we can.
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!hasExtension(display, "EGL_KHR_no_config_context")) {
        const EGLint wanted[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_NONE};
        EGLint count = 0;
        if (!eglChooseConfig(display, wanted, &config, 1, &count) || count == 0) {
            why = "no OpenGL config";
            return EGL_NO_CONTEXT;
        }
    }
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION_KHR, 4,
                                 EGL_CONTEXT_MINOR_VERSION_KHR, 5,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK_KHR, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT_KHR,
                                 EGL_NONE};
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, attributes);
    if (context == EGL_NO_CONTEXT) {
        why = "eglCreateContext 4.5 core failed (" + errorName(eglGetError()) + ")";
        return EGL_NO_CONTEXT;
    }
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        why = "eglMakeCurrent failed (" + errorName(eglGetError()) + ")";
        eglDestroyContext(display, context);
        return EGL_NO_CONTEXT;
    }
    return context;
}

// The displays to try, in order, each with a label for error messages: the devices (hardware first,
// spread by nodeRank, gl/device_order.h), then Mesa's surfaceless platform, then the default display.
std::vector<std::pair<EGLDisplay, std::string>> candidateDisplays(int nodeRank)
{
    std::vector<std::pair<EGLDisplay, std::string>> displays;
    const char* requested = std::getenv("AURORAWALL_EGL_DEVICE");
    if (requested && (*requested == '\0' || std::strlen(requested) > 4 ||
                      std::strspn(requested, "0123456789") != std::strlen(requested)))
        throw std::runtime_error("EGL: AURORAWALL_EGL_DEVICE=" + std::string(requested) +
                                 " is not a device number (0, 1, 2, ...)");
    auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    if (hasExtension(EGL_NO_DISPLAY, "EGL_EXT_platform_device") && queryDevices) {
        EGLDeviceEXT devices[16];
        EGLint count = 0;
        queryDevices(16, devices, &count);
        // Mesa lists its CPU renderer as a device too (EGL_MESA_device_software); where the device's
        // extensions cannot be asked, every device counts as hardware.
        auto queryDeviceString =
            reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
        std::vector<bool> software;
        for (EGLint i = 0; i < count; ++i)
            software.push_back(queryDeviceString &&
                               listsExtension(queryDeviceString(devices[i], EGL_EXTENSIONS), "EGL_MESA_device_software"));
        for (int i : deviceOrder(software, nodeRank))
            if (!requested || std::atoi(requested) == i)
                displays.emplace_back(eglGetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr),
                                      "device " + std::to_string(i));
        if (requested && displays.empty())
            throw std::runtime_error("EGL: AURORAWALL_EGL_DEVICE=" + std::string(requested) + " but there are " +
                                     std::to_string(count) + " devices");
    }
    if (requested)
        return displays;
    if (hasExtension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless"))
        displays.emplace_back(eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr),
                              "surfaceless");
    displays.emplace_back(eglGetDisplay(EGL_DEFAULT_DISPLAY), "default display");
    return displays;
}

} // namespace

std::unique_ptr<Context> createEglContext(int nodeRank)
{
    std::string failures;
    for (const auto& [display, label] : candidateDisplays(nodeRank)) {
        std::string why;
        EGLContext context = createCoreContext(display, why);
        if (context != EGL_NO_CONTEXT) {
            auto result = std::make_unique<EglContext>(display, context);
            result->makeCurrent(0);
            return result;
        }
        failures += (failures.empty() ? "" : "; ") + label + ": " + why;
    }
    throw std::runtime_error("EGL: no display offers OpenGL 4.5 core (" + failures + ")");
}

} // namespace aurorawall::gl
