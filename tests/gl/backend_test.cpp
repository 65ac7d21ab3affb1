#include "gl/backend.h"

#include <gtest/gtest.h>

#include <set>

namespace aurorawall::gl {
namespace {

TEST(Backend, EveryBackendHasItsOwnName)
{
    std::set<std::string> names;
    for (Backend b : {Backend::Egl, Backend::Osmesa, Backend::Glfw})
        names.insert(backendName(b));
    EXPECT_EQ(names, (std::set<std::string>{"egl", "osmesa", "glfw"}));
}

} // namespace
} // namespace aurorawall::gl
