#pragma once
// The per-backend factories behind createContext (private to aw_gl).
#include "gl/context.h"

namespace aurorawall::gl {

std::unique_ptr<Context> createEglContext(int nodeRank);
std::unique_ptr<Context> createOsmesaContext();
std::unique_ptr<Context> createGlfwContext(const std::vector<WindowSpec>& windows);

} // namespace aurorawall::gl
