#include "gl/backend.h"

namespace aurorawall::gl {

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
