#include "app/web/downloads.h"
#include "scene/scene.h"

#include <toml.hpp>

#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace aurorawall::app::web {

namespace {

namespace fs = std::filesystem;

// Sorted tables: the embedded scene reads in the same order at every download.
using Toml = toml::basic_value<toml::discard_comments, std::map, std::vector>;

Toml parse(std::istream& in, const std::string& name)
{
    try {
        return toml::parse<toml::discard_comments, std::map, std::vector>(in, name);
    } catch (const std::exception& e) {
        std::string reason = e.what();
        reason = reason.substr(0, reason.find('\n'));
        throw std::runtime_error(name + ": " + reason);
    }
}

Toml parseFile(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw std::runtime_error(path.string() + ": the base scene cannot be read (moved or removed since the recording?)");
    return parse(in, path.string());
}

bool isTable(const Toml& v, const std::string& key) { return v.is_table() && v.contains(key) && v.at(key).is_table(); }

// A component's table over its base's: key by key, into subtables; arrays (of tables too) whole.
void mergeInto(Toml& base, const Toml& derived)
{
    for (const auto& [key, value] : derived.as_table()) {
        if (value.is_table() && isTable(base, key))
            mergeInto(base.as_table().at(key), value);
        else
            base.as_table()[key] = value;
    }
}

// The scene `file` (read from a file in `folder`) with its base scenes resolved into it.
Toml resolved(Toml file, const fs::path& folder, int depth)
{
    if (!isTable(file, "scene") || !file.at("scene").contains("base"))
        return file;
    if (depth >= scene::kMaxBaseScenes)
        throw std::runtime_error("scenes derive from each other more than " + std::to_string(scene::kMaxBaseScenes) +
                                 " deep (a cycle?)");
    const Toml& baseName = file.at("scene").at("base");
    if (!baseName.is_string())
        throw std::runtime_error("[scene] base must be a string");
    const fs::path basePath = (folder / fs::path(baseName.as_string().str)).lexically_normal();
    Toml out = resolved(parseFile(basePath), basePath.parent_path(), depth + 1);
    if (!out.is_table() || !isTable(out, "scene"))
        throw std::runtime_error(basePath.string() + ": no [scene] table");
    for (const auto& [key, value] : file.as_table()) {
        if (key == "scene") {
            for (const auto& [k, v] : value.as_table())
                if (k != "base")
                    out.as_table()["scene"].as_table()[k] = v;
        } else if (key == "camera" || !value.is_table() || !isTable(out, key)) {
            out.as_table()[key] = value; // the camera whole, as the reader takes it
        } else {
            mergeInto(out.as_table()[key], value);
        }
    }
    // A derived scene may list fewer components: their tables would be unknown to the reader.
    std::set<std::string> listed;
    const Toml& meta = out.at("scene");
    if (meta.contains("components") && meta.at("components").is_array())
        for (const Toml& name : meta.at("components").as_array())
            if (name.is_string())
                listed.insert(name.as_string().str);
    for (auto it = out.as_table().begin(); it != out.as_table().end();)
        if (it->first != "scene" && it->first != "camera" && !listed.count(it->first))
            it = out.as_table().erase(it);
        else
            ++it;
    return out;
}

// The scene as a file: [scene] first, the components' tables, [camera] last (it may hold a key a
// frame), each as a section of its own; numbers with 17 digits, every double read back exactly.
std::string formatted(const Toml& scene)
{
    std::vector<std::string> order{"scene"};
    for (const auto& [key, value] : scene.as_table())
        if (key != "scene" && key != "camera")
            order.push_back(key);
    order.push_back("camera");
    std::string out;
    for (const std::string& key : order) {
        if (!scene.contains(key))
            continue;
        const Toml& value = scene.at(key);
        out += "\n";
        if (value.is_table()) // a section, never inlined as key = {...}
            out += toml::visit(toml::serializer<Toml>(80u, std::numeric_limits<double>::max_digits10, false, false, {key}),
                               value);
        else
            out += toml::format(Toml(Toml::table_type{{key, value}}));
    }
    return out;
}

} // namespace

std::string recordingForDownload(const std::string& text, const std::string& folder)
{
    std::istringstream in(text);
    const Toml recording = parse(in, "the recording");
    if (!isTable(recording, "scene") || !recording.at("scene").contains("base"))
        return text;
    const std::string base = recording.at("scene").at("base").is_string()
                                 ? recording.at("scene").at("base").as_string().str
                                 : std::string("?");
    const Toml scene = resolved(recording, fs::path(folder), 0);
    // The recording's own comment lines first (what it is), then where its scene came from.
    std::string out;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line) && !line.empty() && line.front() == '#';)
        out += line + "\n";
    out += "# Self-contained: the base scene " + fs::path(base).filename().string() +
           " and the scenes it derives from are embedded, resolved as the scene reader does.\n";
    return out + formatted(scene);
}

} // namespace aurorawall::app::web
