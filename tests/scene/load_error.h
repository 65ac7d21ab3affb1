#pragma once
// The message of the InputError that loading a scene throws ("" if none): from a file, or from a
// text written into the test's temporary folder under a name.
#include "common/input_error.h"
#include "components/registry.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

namespace aurorawall::test {

inline std::string loadError(const std::string& file)
{
    try {
        components::loadScene(file);
    } catch (const common::InputError& e) {
        return e.what();
    }
    return "";
}

// Writes `text` as the scene file `name` in the test's temporary folder and returns its path.
inline std::string temporarySceneFile(const std::string& name, const std::string& text)
{
    const std::string path = ::testing::TempDir() + name;
    std::ofstream(path) << text;
    return path;
}

inline std::string loadErrorOfText(const std::string& name, const std::string& text)
{
    return loadError(temporarySceneFile(name, text));
}

} // namespace aurorawall::test
