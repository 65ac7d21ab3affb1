#pragma once
// The options of `aurorawall render`, parsed with Boost.Program_options.
#include <cstdint>
#include <string>

namespace aurorawall::app {

struct RenderOptions {
    std::string wallFile;
    std::string sceneFile;
    std::string backend = "egl";
    std::string outDir = "out";
    std::string statsFile;
    std::string dataDir; // empty: see common/data_dir.h
    std::string toneMap = "aces";
    long long frames = 1;
    double timeStepS = -1.0;   // < 0: the scene's
    double startTimeS = 0.0;
    bool startTimeGiven = false;
    double exposure = 0.0;     // 0: the scene's
    bool realTime = false;
    bool gather = false;
    bool tiles = false;
    bool singleScreen = false;
    std::string balance = "auto"; // on, off, or auto: on when more than one rank renders
    int balanceBands = 8;
    std::string balanceBy = "time"; // time or work: what the balancer equalizes
    int drawLanes = 0;         // 0: every rank draws at once (MpiWorld::beginTurn)
    bool quiet = false;
    bool verbose = false;
    bool help = false;
    std::string helpText;
};

// Throws InputError naming the option for malformed or absurd values.
RenderOptions parseRenderOptions(int argc, char** argv);

} // namespace aurorawall::app
