// Headless OSMesa (Mesa's off-screen library). Its header pulls in <GL/gl.h>, so this file uses no
// other GL header; rendering goes to our own framebuffers, the 1x1 buffer only satisfies OSMesa.
#include "gl/backends.h"
#include "gl/loader.h"

#include <GL/osmesa.h>

#include <stdexcept>
#include <string>

namespace aurorawall::gl {
namespace {

void* osmesaProcAddress(const char* name)
{
    return reinterpret_cast<void*>(OSMesaGetProcAddress(name));
}

class OsmesaContext : public Context {
public:
    explicit OsmesaContext(OSMesaContext context) : context_(context) {}
    ~OsmesaContext() override { OSMesaDestroyContext(context_); }

    void makeCurrent(int window) override
    {
        if (window != 0)
            throw std::logic_error("OSMesa: headless context has no window " + std::to_string(window));
        if (!OSMesaMakeCurrent(context_, buffer_, GL_UNSIGNED_BYTE, 1, 1))
            throw std::runtime_error("OSMesa: OSMesaMakeCurrent failed");
        loadFunctions(osmesaProcAddress);
    }

private:
    OSMesaContext context_;
    unsigned char buffer_[4] = {};
};

} // namespace

std::unique_ptr<Context> createOsmesaContext()
{
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA,
                              OSMESA_DEPTH_BITS, 0,
                              OSMESA_STENCIL_BITS, 0,
                              OSMESA_ACCUM_BITS, 0,
                              OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION, 4,
                              OSMESA_CONTEXT_MINOR_VERSION, 5,
                              0};
    OSMesaContext context = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!context)
        throw std::runtime_error("OSMesa: OSMesaCreateContextAttribs gave no OpenGL 4.5 core context");
    auto result = std::make_unique<OsmesaContext>(context);
    result->makeCurrent(0);
    return result;
}

} // namespace aurorawall::gl
