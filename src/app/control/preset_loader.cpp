#include "app/control/preset_loader.h"

#include "app/control/command.h"
#include "components/registry.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <vector>

namespace aurorawall::app::control {

namespace {

// The names of the presets in `presetDir`, blank-separated, sorted.
std::string presetNames(const std::string& presetDir)
{
    std::vector<std::string> names;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(presetDir, error))
        if (entry.path().extension() == ".toml")
            names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    std::string text;
    for (const std::string& n : names)
        text += (text.empty() ? "" : " ") + n;
    return text;
}

std::string oneLine(std::string text)
{
    std::replace(text.begin(), text.end(), '\n', ' ');
    return text;
}

// The camera of the scene file `path` of preset `name`.
scene::Camera cameraOf(const std::string& name, const std::string& path)
{
    try {
        return components::loadScene(path).camera;
    } catch (const std::exception& e) {
        throw CommandError("preset " + name + ": " + oneLine(e.what()));
    }
}

} // namespace

std::string presetPath(const std::string& name, const std::string& presetDir)
{
    const bool file = name.size() > 5 && name.compare(name.size() - 5, 5, ".toml") == 0;
    if (!file && name.find('/') != std::string::npos)
        throw CommandError("preset " + name + ": a preset is a name (" + presetNames(presetDir) +
                           ") or a scene file ending in .toml");
    const std::string path = file ? name : presetDir + "/" + name + ".toml";
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error))
        throw CommandError("preset " + name + ": " +
                           (file ? path + " is not a readable file"
                                 : "no such preset in " + presetDir + " (presets: " + presetNames(presetDir) + ")"));
    return path;
}

scene::Camera presetCamera(const std::string& name, const std::string& presetDir)
{
    return cameraOf(name, presetPath(name, presetDir));
}

PresetLoader::~PresetLoader()
{
    if (pending_.valid())
        pending_.wait();
}

void PresetLoader::start(const std::string& name, const std::string& presetDir, std::uint64_t client)
{
    if (pending_.valid())
        throw CommandError("preset " + name + ": another preset is still loading");
    const std::string path = presetPath(name, presetDir);
    pending_ = std::async(std::launch::async, [name, path, client] {
        Loaded loaded{client, name, std::nullopt, ""};
        try {
            loaded.camera = cameraOf(name, path);
        } catch (const std::exception& e) {
            loaded.error = e.what();
        }
        return loaded;
    });
}

std::optional<PresetLoader::Loaded> PresetLoader::poll()
{
    if (!pending_.valid() || pending_.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
        return std::nullopt;
    return pending_.get();
}

} // namespace aurorawall::app::control
