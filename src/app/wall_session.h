#pragma once
// What a rank sets up once before the frame loop of `aurorawall render`: the configuration
// (identical on every rank), its GL context and windows, the raymarcher compiled for the scene, the
// float targets of its screens, and the bands every frame is drawn in.
#include "app/console_view.h"
#include "app/control/control_server.h"
#include "app/render_options.h"
#include "app/screen_target.h"
#include "app/web/web_console.h"
#include "cluster/load_balancer.h"
#include "cluster/mpi_world.h"
#include "gl/context.h"
#include "io/tone_map.h"
#include "render/tile_renderer.h"
#include "render/window_presenter.h"
#include "scene/scene.h"
#include "wall/wall.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace aurorawall::app {

struct WallSession {
    RenderOptions options;
    wall::Wall wall;
    scene::Scene scene;
    std::string dataDir;   // --data-dir, else the installed or source tree's (common/data_dir.h)
    std::string shaderDir; // dataDir/shaders
    double exposure = 1.0; // --exposure, else the scene's
    io::ToneMap toneMap;   // windows and wall.png
    // GL objects below the context, so that they are deleted while it exists.
    std::unique_ptr<gl::Context> context;
    std::unique_ptr<render::TileRenderer> renderer;
    std::unique_ptr<render::WindowPresenter> presenter; // windows only
    std::vector<ScreenTarget> screens;                   // this rank's, in wall order
    std::unique_ptr<ConsoleView> console;                // master with --console only
    // The bands of every frame: with load balancing each screen cut into --balance-bands bands,
    // otherwise one band per screen, always drawn by the screen's own rank (the static split).
    std::vector<cluster::Band> bands;
    bool balanced = false;
    std::unique_ptr<control::ControlServer> control; // master with --control-port only
    std::unique_ptr<web::WebConsole> web;            // master with --web-port only
    std::string movieError; // master: why a --movie frame could not be written (the run then stops)
    std::string recordError; // master: why the --record-path file could not be written
    std::string statsError;  // master: why a --stats row could not be written (the run then stops)
    int stoppedBySignal = 0; // master: SIGINT or SIGTERM ended the run (app/stop_signal.h)
};

// Runs one step on every rank and agrees on its outcome: the largest exit status over the ranks
// (cli/exit_status.h: 0 if no rank threw, 2 for a usage error, 1 for any other), on every rank;
// rank 0 has printed each distinct reason once.
int agreedStep(const cluster::MpiWorld& world, const std::function<void()>& step);

// Parses the options, loads wall and scene, checks the output paths, opens the context (and
// windows), compiles the raymarcher and makes the screens' targets. Returns the exit status every
// rank agrees on; 0 also after --help (session.options.help, the help printed by rank 0).
int setUpWallSession(const cluster::MpiWorld& world, int argc, char** argv, WallSession& session);

} // namespace aurorawall::app
