#include "app/control/remote_control.h"

#include "app/control/command.h"
#include "app/control/geographic_camera.h"
#include "app/control/orbit.h"
#include "app/control/output_path.h"
#include "common/formatted.h"
#include "components/registry.h"

#include <algorithm>
#include <filesystem>
#include <set>

namespace aurorawall::app::control {

using common::formatted;

namespace {

// time T: the clock set to T. A flying camera moves with the time: no farther from the planet than
// goto may put it.
std::string setTime(double timeS, cluster::MasterClock& clock, double planetRadiusKm)
{
    const double altitudeKm = scene::altitudeKm(clock.cameraAt(timeS).positionKm, planetRadiusKm);
    if (!(altitudeKm <= kMaxAltitudeKm))
        throw CommandError(formatted("time: the camera, flying at %.6g km/s, would be %.3g km above the ground "
                                  "(at most 1e6 km, as for goto)",
                                  clock.camera().speedKmPerS, altitudeKm));
    clock.setTime(timeS);
    return formatted("ok time_s=%.12g", timeS);
}

// goto LAT LON ALT (degrees, degrees, km): the camera moved there, its heading and pitch kept.
std::string moveTo(const double* v, cluster::MasterClock& clock, double planetRadiusKm, FrameRequests& requests)
{
    const scene::Camera now = clock.camera();
    GeographicPose pose = poseOf(now, planetRadiusKm);
    pose.latitudeDeg = v[0];
    pose.longitudeDeg = v[1];
    pose.altitudeKm = v[2];
    clock.setCamera(cameraAt(pose, planetRadiusKm, now.speedKmPerS));
    requests.orbit = OrbitRequest::Stop;
    return formatted("ok goto lat_deg=%.9g lon_deg=%.9g alt_km=%.9g", v[0], v[1], v[2]);
}

// look HEADING PITCH (degrees): the camera turned where it stands.
std::string turnTo(const double* v, cluster::MasterClock& clock, double planetRadiusKm, FrameRequests& requests)
{
    const scene::Camera now = clock.camera();
    GeographicPose pose = poseOf(now, planetRadiusKm);
    pose.headingDeg = v[0];
    pose.pitchDeg = v[1];
    clock.setCamera(cameraAt(pose, planetRadiusKm, now.speedKmPerS));
    requests.orbit = OrbitRequest::Stop;
    return formatted("ok look heading_deg=%.9g pitch_deg=%.9g", v[0], v[1]);
}

// orbit LAT LON ALT (degrees, degrees, km): the camera aimed at that point and circling it.
std::string startOrbit(const double* v, cluster::MasterClock& clock, double planetRadiusKm, FrameRequests& requests)
{
    const glm::dvec3 pivot = scene::planetPoint(v[0], v[1], planetRadiusKm + v[2]);
    const scene::Camera now = clock.camera();
    const double distanceKm = glm::length(pivot - now.positionKm);
    if (distanceKm < 1e-3)
        throw CommandError("orbit: the camera is at that point (less than 1 m away)");
    clock.setCamera(aimedAt(now, pivot));
    requests.orbit = OrbitRequest::Start;
    requests.pivotKm = pivot;
    return formatted("ok orbit lat_deg=%.9g lon_deg=%.9g alt_km=%.9g", v[0], v[1], v[2]) +
           formatted(" distance_km=%.6f", distanceKm);
}

// screenshot PATH: the request queued for this frame, answered once written (inside the output
// folder only: output_path.h).
void requestScreenshot(const std::string& path, std::uint64_t client, const WallStatus& status, const WallFacts& wall,
                       FrameRequests& requests)
{
    const std::string full = insideOutputFolder("screenshot " + path, path, wall.outputDir).string();
    if (requests.screenshots.empty() && status.sinceScreenshotS < kScreenshotIntervalS)
        throw CommandError("screenshot " + path + ": the last was taken less than 0.5 s ago (at most 2 "
                           "a second; --movie records every frame)");
    std::set<std::string> files; // this frame's: a file asked for again is written once
    for (const ScreenshotRequest& r : requests.screenshots)
        files.insert(r.path);
    if (!files.count(full) && files.size() >= kScreenshotsPerFrame)
        throw CommandError("screenshot " + path + ": at most 4 files in one frame");
    requests.screenshots.push_back({client, full});
}

// `record start|stop`, `movie start|stop` checked against what runs (and what this frame's earlier
// lines have asked): one recording and one movie at a time, a stop only while one runs.
OutputRequest outputRequest(const Command& command, std::uint64_t client, const WallStatus& status,
                            const WallFacts& wall, const FrameRequests& requests)
{
    const bool record = command.kind == CommandKind::RecordStart || command.kind == CommandKind::RecordStop;
    const bool start = command.kind == CommandKind::RecordStart || command.kind == CommandKind::MovieStart;
    const CommandKind startKind = record ? CommandKind::RecordStart : CommandKind::MovieStart;
    const CommandKind stopKind = record ? CommandKind::RecordStop : CommandKind::MovieStop;
    std::string running = record ? status.recording : status.movie;
    for (const OutputRequest& r : requests.outputs)
        if (r.kind == startKind)
            running = r.path;
        else if (r.kind == stopKind)
            running.clear();
    const std::string word = record ? "record" : "movie";
    if (!start) {
        if (running.empty())
            throw CommandError(word + " stop: no " + (record ? "recording" : "movie") + " runs (" + word +
                               " start " + (record ? "PATH.toml" : "DIR") + " starts one)");
        return {command.kind, client, "", running};
    }
    const std::string what = word + " start " + command.path;
    if (!running.empty())
        throw CommandError(what + ": " + (record ? "a recording" : "a movie") + " into " + running + " runs (" + word +
                           " stop first)");
    const std::filesystem::path full = insideOutputFolder(what, command.path, wall.outputDir);
    std::error_code error;
    if (record && std::filesystem::is_directory(full, error))
        throw CommandError(what + ": " + full.string() + " is a folder");
    if (!record && std::filesystem::exists(full, error) && !std::filesystem::is_directory(full, error))
        throw CommandError(what + ": " + full.string() + " is not a folder");
    if (!record && std::filesystem::exists(full / "frames.csv", error))
        throw CommandError(what + ": " + full.string() + " already holds a movie (frames.csv); give another folder");
    return {command.kind, client, command.path, full.string(), command.exr};
}

// Carries out one command; returns its answer ("" for a screenshot, answered once written).
std::string carryOut(const Command& command, std::uint64_t client, cluster::MasterClock& clock,
                     const WallStatus& status, const WallFacts& wall, PresetLoader& presets, FrameRequests& requests)
{
    const double planetRadiusKm = wall.planetRadiusKm;
    const double* v = command.values;
    switch (command.kind) {
    case CommandKind::Status:
        return statusLine(clock, status, planetRadiusKm);
    case CommandKind::Pause:
        clock.pause();
        return formatted("ok paused at time_s=%.12g", clock.timeS());
    case CommandKind::Play:
        clock.play();
        return formatted("ok playing from time_s=%.12g", clock.timeS());
    case CommandKind::Speed:
        clock.setSpeed(v[0]);
        return formatted("ok speed %.12g", v[0]);
    case CommandKind::Step:
        if (!clock.paused())
            throw CommandError("step: the clock is playing (pause first)");
        clock.step();
        return "ok step";
    case CommandKind::Time:
        return setTime(v[0], clock, planetRadiusKm);
    case CommandKind::Goto:
        return moveTo(v, clock, planetRadiusKm, requests);
    case CommandKind::Look:
        return turnTo(v, clock, planetRadiusKm, requests);
    case CommandKind::Preset:
        presets.start(command.path, wall.presetDir, client);
        return ""; // answered once loaded (applyLoadedPreset)
    case CommandKind::Orbit:
        return startOrbit(v, clock, planetRadiusKm, requests);
    case CommandKind::OrbitOff:
        requests.orbit = OrbitRequest::Stop;
        return "ok orbit off";
    case CommandKind::Screenshot:
        requestScreenshot(command.path, client, status, wall, requests);
        return "";
    case CommandKind::RecordStart:
    case CommandKind::RecordStop:
    case CommandKind::MovieStart:
    case CommandKind::MovieStop:
        requests.outputs.push_back(outputRequest(command, client, status, wall, requests));
        return "";
    case CommandKind::Quit:
        requests.quit = true;
        return "ok quit";
    }
    return "";
}

} // namespace

std::string statusLine(const cluster::MasterClock& clock, const WallStatus& status, double planetRadiusKm)
{
    const GeographicPose p = poseOf(clock.camera(), planetRadiusKm);
    return "ok frame=" + std::to_string(status.frame) + formatted(" time_s=%.12g fps=%.3g", clock.timeS(), status.fps) +
           (clock.paused() ? " paused" : " playing") + formatted(" speed=%.12g", clock.speed()) +
           formatted(" lat_deg=%.6f lon_deg=%.6f alt_km=%.6f", p.latitudeDeg, p.longitudeDeg, p.altitudeKm) +
           formatted(" heading_deg=%.6f pitch_deg=%.6f", p.headingDeg, p.pitchDeg);
}

// A preset whose load has finished: its camera applied and the command answered.
void applyLoadedPreset(CommandChannel& channel, cluster::MasterClock& clock, PresetLoader& presets,
                       double planetRadiusKm, FrameRequests& requests)
{
    std::optional<PresetLoader::Loaded> loaded = presets.poll();
    if (!loaded)
        return;
    if (!loaded->camera) {
        channel.answer(loaded->client, "error " + loaded->error);
        return;
    }
    clock.setCamera(*loaded->camera);
    requests.orbit = OrbitRequest::Stop;
    const GeographicPose p = poseOf(clock.camera(), planetRadiusKm);
    channel.answer(loaded->client, "ok preset " + loaded->name +
                                      formatted(" lat_deg=%.6f lon_deg=%.6f alt_km=%.6f", p.latitudeDeg, p.longitudeDeg,
                                             p.altitudeKm));
}

FrameRequests serveCommands(CommandChannel& channel, cluster::MasterClock& clock, const WallStatus& status,
                            const WallFacts& wall, PresetLoader& presets)
{
    FrameRequests requests;
    applyLoadedPreset(channel, clock, presets, wall.planetRadiusKm, requests);
    for (const ControlLine& line : channel.poll(kCommandsPerFrame)) {
        std::string answer;
        try {
            if (requests.quit)
                throw CommandError("the wall is quitting");
            answer = carryOut(parseCommand(line.text), line.client, clock, status, wall, presets, requests);
        } catch (const CommandError& e) {
            answer = std::string("error ") + e.what();
        }
        if (!answer.empty())
            channel.answer(line.client, answer);
    }
    return requests;
}

} // namespace aurorawall::app::control
