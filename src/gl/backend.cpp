#include "gl/backend.h"

#include "common/input_error.h"

namespace aurorawall::gl {

Backend parseBackend(const std::string& name)
{
    for (Backend b : {Backend::Egl, Backend::Osmesa, Backend::Glfw})
        if (name == backendName(b))
            return b;
    throw InputError("--backend: unknown backend '" + name + "' (expected egl, osmesa or glfw)");
}

std::string backendName(Backend backend)
{
    switch (backend) {
    case Backend::Egl: return "egl";
    case Backend::Osmesa: return "osmesa";
    case Backend::Glfw: return "glfw";
    }
    return "?";
}

} // namespace aurorawall::gl
