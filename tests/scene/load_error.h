#pragma once
// The message of the InputError that loading the scene `file` throws ("" if none).
#include "common/input_error.h"
#include "components/registry.h"

#include <string>

namespace aurorawall::test {

inline std::string loadError(const std::string& file)
{
    try {
        components::loadScene(file);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

} // namespace aurorawall::test
