#include "gl/backend.h"

#include "common/input_error.h"

#include <gtest/gtest.h>

namespace aurorawall::gl {
namespace {

TEST(Backend, ParsesEveryName)
{
    for (Backend b : {Backend::Egl, Backend::Osmesa, Backend::Glfw})
        EXPECT_EQ(parseBackend(backendName(b)), b);
    EXPECT_EQ(parseBackend("osmesa"), Backend::Osmesa);
}

TEST(Backend, UnknownNameNamesTheOption)
{
    for (const char* bad : {"", "EGL", "vulkan", "egl "}) {
        try {
            parseBackend(bad);
            ADD_FAILURE() << "accepted '" << bad << "'";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("--backend"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("'" + std::string(bad) + "'"), std::string::npos) << e.what();
        }
    }
}

} // namespace
} // namespace aurorawall::gl
