#include "app/path_recorder.h"

#include "config/toml_string.h"
#include "io/atomic_file.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace aurorawall::app {

namespace fs = std::filesystem;

namespace {

// A TOML float that reads back as the same double: 17 significant digits (IEEE 754 binary64 needs
// at most 17 to round-trip), with a decimal point so that TOML does not read an integer.
std::string number(double x)
{
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", x);
    std::string s = text;
    if (s.find_first_of(".en") == std::string::npos)
        s += ".0";
    return s;
}

std::string vector3(const glm::dvec3& v)
{
    return "[" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + "]";
}

// The base scene as the recorded file names it: relative to the file's folder (the scene reader
// resolves it from there), absolute when no relative path exists (another drive).
std::string basePath(const std::string& file, const std::string& baseScene)
{
    const fs::path base = fs::absolute(baseScene).lexically_normal();
    const fs::path folder = fs::absolute(file).parent_path();
    const fs::path relative = base.lexically_relative(folder);
    return relative.empty() ? base.generic_string() : relative.generic_string();
}

} // namespace

PathRecorder::PathRecorder(std::string file, std::string baseScene, double startTimeS, double timeStepS)
    : file_(std::move(file)), baseScene_(std::move(baseScene)), startTimeS_(startTimeS), timeStepS_(timeStepS)
{
}

void PathRecorder::add(const cluster::FrameState& state)
{
    while (!cameras_.empty() && !(cameras_.back().timeS < state.timeS))
        cameras_.pop_back();
    cameras_.push_back({state.timeS, state.cameraPositionKm, -state.cameraBack, state.cameraUp, state.zoom});
}

std::string PathRecorder::text() const
{
    std::ostringstream out;
    out << "# The camera flown by `aurorawall render --record-path`, one key per frame.\n"
        << "[scene]\n"
        << "base = " << config::tomlBasicString(basePath(file_, baseScene_)) << "\n"
        << "start_time_s = " << number(startTimeS_) << "\n"
        << "time_step_s = " << number(timeStepS_) << "\n";
    std::vector<RecordedCamera> keys = cameras_;
    if (keys.size() == 1 && keys.front().zoom != 1.0) {
        keys.push_back(keys.front());
        keys.back().timeS += timeStepS_ > 0.0 ? timeStepS_ : 1.0;
    }
    if (keys.size() == 1) {
        const RecordedCamera& c = keys.front();
        out << "\n[camera]\n"
            << "position_km = " << vector3(c.positionKm) << "\n"
            << "direction = " << vector3(c.forward) << "\n"
            << "up = " << vector3(c.up) << "\n";
    }
    if (keys.size() > 1) {
        for (const RecordedCamera& c : keys) {
            out << "\n[[camera.key]]\n"
                << "time_s = " << number(c.timeS) << "\n"
                << "position_km = " << vector3(c.positionKm) << "\n"
                << "direction = " << vector3(c.forward) << "\n"
                << "up = " << vector3(c.up) << "\n";
            if (c.zoom != 1.0)
                out << "zoom = " << number(c.zoom) << "\n";
        }
    }
    return out.str();
}

void PathRecorder::write() const
{
    const std::string content = text();
    io::writeFileAtomically(file_, [&content](const std::string& temporary) {
        std::ofstream out(temporary, std::ios::binary);
        out << content;
        out.close();
        if (!out)
            throw std::runtime_error(temporary + ": cannot write");
    });
}

} // namespace aurorawall::app
