#include "gl/functions.h"
#include "gl/debug_layer.h"
#include "gl/loader.h"

#include <stdexcept>
#include <string>

namespace aurorawall::gl {

#define AURORAWALL_GL_DEFINE(type, name) type name = nullptr;
AURORAWALL_GL_FUNCTIONS(AURORAWALL_GL_DEFINE)
#undef AURORAWALL_GL_DEFINE

namespace {
ProcAddressFunction loadedFrom = nullptr;
}

void loadFunctions(ProcAddressFunction getProcAddress)
{
    if (getProcAddress == loadedFrom)
        return;
    loadedFrom = nullptr;
    std::string missing;
#define AURORAWALL_GL_LOAD(type, name)                                         \
    name = reinterpret_cast<type>(getProcAddress(#name));                      \
    if (!name)                                                                 \
        missing += std::string(missing.empty() ? "" : ", ") + #name;
    AURORAWALL_GL_FUNCTIONS(AURORAWALL_GL_LOAD)
#undef AURORAWALL_GL_LOAD
    if (!missing.empty())
        throw std::runtime_error("OpenGL loader: the context lacks " + missing);
    if (debugModes().any())
        installDebugLayer(debugModes());
    loadedFrom = getProcAddress;
}

void forgetFunctions()
{
#define AURORAWALL_GL_CLEAR(type, name) name = nullptr;
    AURORAWALL_GL_FUNCTIONS(AURORAWALL_GL_CLEAR)
#undef AURORAWALL_GL_CLEAR
    loadedFrom = nullptr;
}

} // namespace aurorawall::gl
