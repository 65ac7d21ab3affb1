#pragma once
// The options of `aurorawall render`, parsed through cli/command_line.h.
#include "cluster/rank_message.h"
#include "gl/backend.h"
#include "io/tone_map.h"

#include <string>

namespace aurorawall::app {

// --balance: whether ranks share their screens' bands; Auto: when more than one rank renders.
enum class Balance { On, Off, Auto };

// --march: the shader stage of the raymarcher (render/march_shader.h); Auto: chosen for the device
// (render::preferredMarchStage).
enum class MarchChoice { Auto, Compute, Fragment };

struct RenderOptions {
    std::string wallFile;
    std::string sceneFile;
    gl::Backend backend = gl::Backend::Egl;
    MarchChoice march = MarchChoice::Auto;
    std::string outDir = "out";
    std::string statsFile;
    std::string costMapFile; // --cost-map; empty: none
    std::string dataDir; // empty: see common/data_dir.h
    io::ToneMap::Curve toneMap = io::ToneMap::Curve::AcesFilmic;
    long long frames = 1;
    double timeStepS = -1.0;   // < 0: the scene's
    double startTimeS = 0.0;
    bool startTimeGiven = false;
    double exposure = 0.0;     // 0: the scene's
    bool realTime = false;
    bool gather = false;
    bool tiles = false;
    bool singleScreen = false;
    Balance balance = Balance::Auto;
    int balanceBands = 8;
    cluster::BandMeasure balanceBy = cluster::BandMeasure::Time; // what the balancer equalizes
    int controlPort = -1;                // --control-port; -1: no remote control, 0: a free port
    std::string controlBind = "127.0.0.1"; // --control-bind
    std::string controlTokenFile;        // --control-token-file: the shared secret clients send first; empty: none
    int webPort = -1;                    // --web-port: the browser console; -1: none, 0: a free port
    double rankTimeoutS = 10.0;          // --rank-timeout: a rank silent or hung this long ends the job (status 3)
    std::string movieDir;                // --movie: every frame's wall as OUT/frame-NNNNNN.png; empty: none
    bool movieExr = false;               // --movie-exr: also frame-NNNNNN.exr
    std::string recordPath;              // --record-path: the master writes the flown camera as a scene (.toml); empty: none
    bool console = false;                // --console: the master's preview window of the whole wall
    bool quiet = false;
    bool verbose = false;
    bool printRanks = false;             // --print-ranks: print the wall's rank count and exit (for launch scripts)
    bool help = false;
    std::string helpText;
};

// Throws UsageError naming the option for an unknown, missing, malformed or absurd option.
RenderOptions parseRenderOptions(int argc, char** argv);

} // namespace aurorawall::app
