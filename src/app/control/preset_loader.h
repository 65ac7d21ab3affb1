#pragma once
// `preset NAME` off the frame loop: the preset's scene file is read and checked on a worker thread,
// so that a large file (up to the scene files' size limit, docs/scenes.md) never stalls the wall.
// The frame loop polls once a frame; the camera is applied, and the command answered, at the first
// frame boundary after the load has finished. One load at a time.
#include "scene/scene.h"

#include <cstdint>
#include <future>
#include <optional>
#include <string>

namespace aurorawall::app::control {

class PresetLoader {
public:
    PresetLoader() = default;
    PresetLoader(const PresetLoader&) = delete;
    PresetLoader& operator=(const PresetLoader&) = delete;
    ~PresetLoader();

    // Checks the name (presetPath) and starts reading the preset for `client`. Throws CommandError
    // "preset NAME: REASON" for a bad name, or while another preset loads.
    void start(const std::string& name, const std::string& presetDir, std::uint64_t client);

    struct Loaded {
        std::uint64_t client = 0;
        std::string name;
        std::optional<scene::Camera> camera; // empty: the file is no scene, see error
        std::string error;                   // "preset NAME: REASON"
    };
    // The finished load, once; nothing while none has finished.
    std::optional<Loaded> poll();

    bool loading() const { return pending_.valid(); }

private:
    std::future<Loaded> pending_;
};

// The camera of the preset `name`: of presetDir/NAME.toml, or of the scene file `name` if it ends in
// .toml (the camera that scene renders with: its [camera], or its base scene's). A keyed camera path
// comes with it, so the camera follows the preset's flight at the wall's animation time. Throws
// CommandError "preset NAME: REASON" for an unknown preset or a file that is no scene. Reads the file
// on the calling thread (PresetLoader runs it on its own).
scene::Camera presetCamera(const std::string& name, const std::string& presetDir);

// The file of preset `name`: presetDir/NAME.toml, or `name` itself if it ends in .toml. Throws
// CommandError "preset NAME: REASON" for a name that is neither, or a file that does not exist.
std::string presetPath(const std::string& name, const std::string& presetDir);

} // namespace aurorawall::app::control
