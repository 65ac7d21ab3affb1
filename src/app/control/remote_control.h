#pragma once
// The wall's remote control on the master: the commands read from its channels (the ControlServer's
// TCP clients, the browser console's requests) are carried out on the master's clock and camera
// (cluster/master_clock.h) before the next frame is decided, so their effect reaches every rank in
// that frame's one broadcast. The protocol: docs/driving.md.
#include "app/control/command.h"
#include "app/control/command_channel.h"
#include "app/control/preset_loader.h"
#include "cluster/master_clock.h"

#include <cstdint>
#include <string>
#include <vector>

namespace aurorawall::app::control {

// Commands carried out per frame at most; more wait for the next frames.
constexpr std::size_t kCommandsPerFrame = 16;

// The wall as the frame loop knows it.
struct WallStatus {
    std::uint64_t frame = 0; // the last frame drawn
    double fps = 0.0;        // frames per second of the master's loop, over the last frame
    double sinceScreenshotS = 1e30; // since the wall was last gathered for screenshots, s
    std::string recording; // the file `record start` is recording into (until `record stop`), else ""
    std::string movie;     // the folder `movie start` is writing into (until `movie stop`), else ""
};

// Screenshots gather the whole wall and write PNGs on the master: at most kScreenshotsPerFrame files
// in one frame (a file asked for again in that frame is written once), and such a frame at most every kScreenshotIntervalS, so that no client, however
// fast it asks, slows the wall by more than one gather every half second (--movie records every frame).
constexpr std::size_t kScreenshotsPerFrame = 4;
constexpr double kScreenshotIntervalS = 0.5;

// A wall image asked for: written by the master after the next frame, then answered.
struct ScreenshotRequest {
    std::uint64_t client = 0;
    std::string path; // inside the output folder
};

// `record start`, `record stop`, `movie start`, `movie stop`: carried out by the frame loop at the
// frame it decides next (the recording's first camera, the movie's first frame), then answered.
struct OutputRequest {
    CommandKind kind = CommandKind::RecordStart;
    std::uint64_t client = 0;
    std::string name; // as given: relative to the output folder
    std::string path; // the output folder's path joined with it
    bool exr = false; // movie start: OpenEXR frames too
};

// What the wall's commands need to know of it.
struct WallFacts {
    double planetRadiusKm = 6371.0;
    std::string presetDir; // where `preset NAME` finds NAME.toml: config/scenes under the data directory
    std::string outputDir; // --out: `screenshot PATH` writes outputDir/PATH, PATH relative and without ..
    // (the same for `record start` and `movie start`)
};

// The orbit the commands leave the navigation in (app/navigation.h).
enum class OrbitRequest {
    Keep,  // as it is
    Stop,  // free flight: `orbit off`, or the camera put elsewhere by goto, look or preset
    Start, // orbit FrameRequests::pivotKm (the camera already looks at it)
};

// What the commands ask of the frame loop beyond the clock.
struct FrameRequests {
    bool quit = false;
    std::vector<ScreenshotRequest> screenshots;
    std::vector<OutputRequest> outputs; // in the order asked
    OrbitRequest orbit = OrbitRequest::Keep;
    glm::dvec3 pivotKm{0.0};
};

// Applies a preset whose load has finished (answering its command), polls the channel once, carries
// out up to kCommandsPerFrame commands and answers each (but the screenshots, answered once written,
// the presets, once loaded, and the recordings and movies, once started or stopped by the frame
// loop). A malformed or unknown line is answered "error REASON".
FrameRequests serveCommands(CommandChannel& channel, cluster::MasterClock& clock, const WallStatus& status,
                            const WallFacts& wall, PresetLoader& presets);

// The answer to `status`: the last frame drawn, and the time and camera the wall shows (those a command
// has just set, if no frame has shown them yet).
std::string statusLine(const cluster::MasterClock& clock, const WallStatus& status, double planetRadiusKm);

} // namespace aurorawall::app::control
