#include "app/control/remote_control.h"

#include "app/control/command.h"
#include "app/control/geographic_camera.h"

#include <cstdio>
#include <filesystem>

namespace aurorawall::control {

namespace {

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0)
{
    char text[160];
    std::snprintf(text, sizeof text, pattern, a, b, c);
    return text;
}

// Carries out one command; returns its answer ("" for a screenshot, answered once written).
std::string carryOut(const Command& command, std::uint64_t client, cluster::MasterClock& clock,
                     const WallStatus& status, double planetRadiusKm, FrameRequests& requests)
{
    const double* v = command.values;
    switch (command.kind) {
    case CommandKind::Status:
        return statusLine(clock, status, planetRadiusKm);
    case CommandKind::Pause:
        clock.pause();
        return format("ok paused at time_s=%.12g", clock.timeS());
    case CommandKind::Play:
        clock.play();
        return format("ok playing from time_s=%.12g", clock.timeS());
    case CommandKind::Speed:
        clock.setSpeed(v[0]);
        return format("ok speed %.12g", v[0]);
    case CommandKind::Step:
        if (!clock.paused())
            throw CommandError("step: the clock is playing (pause first)");
        clock.step();
        return "ok step";
    case CommandKind::Time:
        clock.setTime(v[0]);
        return format("ok time_s=%.12g", v[0]);
    case CommandKind::Goto: {
        const scene::Camera now = clock.camera();
        GeographicPose pose = poseOf(now, planetRadiusKm);
        pose.latitudeDeg = v[0];
        pose.longitudeDeg = v[1];
        pose.altitudeKm = v[2];
        clock.setCamera(cameraAt(pose, planetRadiusKm, now.speedKmPerS));
        return format("ok goto lat_deg=%.9g lon_deg=%.9g alt_km=%.9g", v[0], v[1], v[2]);
    }
    case CommandKind::Look: {
        const scene::Camera now = clock.camera();
        GeographicPose pose = poseOf(now, planetRadiusKm);
        pose.headingDeg = v[0];
        pose.pitchDeg = v[1];
        clock.setCamera(cameraAt(pose, planetRadiusKm, now.speedKmPerS));
        return format("ok look heading_deg=%.9g pitch_deg=%.9g", v[0], v[1]);
    }
    case CommandKind::Screenshot: {
        const std::filesystem::path parent = std::filesystem::path(command.path).parent_path();
        std::error_code error;
        if (!parent.empty() && !std::filesystem::is_directory(parent, error))
            throw CommandError("screenshot " + command.path + ": " + parent.string() + " is not a folder");
        requests.screenshots.push_back({client, command.path});
        return "";
    }
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
    return "ok frame=" + std::to_string(status.frame) + format(" time_s=%.12g fps=%.3g", clock.timeS(), status.fps) +
           (clock.paused() ? " paused" : " playing") + format(" speed=%.12g", clock.speed()) +
           format(" lat_deg=%.6f lon_deg=%.6f alt_km=%.6f", p.latitudeDeg, p.longitudeDeg, p.altitudeKm) +
           format(" heading_deg=%.6f pitch_deg=%.6f", p.headingDeg, p.pitchDeg);
}

FrameRequests serveCommands(ControlServer& server, cluster::MasterClock& clock, const WallStatus& status,
                            double planetRadiusKm)
{
    FrameRequests requests;
    for (const ControlLine& line : server.poll(kCommandsPerFrame)) {
        std::string answer;
        try {
            if (requests.quit)
                throw CommandError("the wall is quitting");
            answer = carryOut(parseCommand(line.text), line.client, clock, status, planetRadiusKm, requests);
        } catch (const CommandError& e) {
            answer = std::string("error ") + e.what();
        }
        if (!answer.empty())
            server.answer(line.client, answer);
    }
    return requests;
}

} // namespace aurorawall::control
