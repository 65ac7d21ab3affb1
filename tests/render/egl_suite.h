#pragma once
// A parameterized test suite whose tests render in one EGL context, made current before its first
// test and released after its last.
#include "gl/context.h"

#include <gtest/gtest.h>

#include <memory>

namespace aurorawall::test {

template <class Param>
class EglSuite : public ::testing::TestWithParam<Param> {
protected:
    static void SetUpTestSuite() { context_ = gl::createContext(gl::Backend::Egl); }
    static void TearDownTestSuite() { context_.reset(); }
    static inline std::unique_ptr<gl::Context> context_;
};

} // namespace aurorawall::test
