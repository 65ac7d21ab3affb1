#pragma once
// What a rank sets up once before the frame loop of `aurorawall render`: the configuration
// (identical on every rank), its GL context and windows, the raymarcher compiled for the scene, the
// float targets of its screens, and the bands every frame is drawn in.
#include "app/render_options.h"
#include "app/screen_target.h"
#include "cluster/load_balancer.h"
#include "cluster/mpi_world.h"
#include "gl/context.h"
#include "io/tone_map.h"
#include "render/tile_renderer.h"
#include "render/window_presenter.h"
#include "scene/scene.h"
#include "wall/wall.h"

#include <memory>
#include <string>
#include <vector>

namespace aurorawall::app {

struct WallSession {
    RenderOptions options;
    wall::Wall wall;
    scene::Scene scene;
    std::string shaderDir;
    double exposure = 1.0; // --exposure, else the scene's
    io::ToneMap toneMap;   // windows and wall.png
    // GL objects below the context, so that they are deleted while it exists.
    std::unique_ptr<gl::Context> context;
    std::unique_ptr<render::TileRenderer> renderer;
    std::unique_ptr<render::WindowPresenter> presenter; // windows only
    std::vector<ScreenTarget> screens;                   // this rank's, in wall order
    // The bands of every frame: with load balancing each screen cut into --balance-bands bands,
    // otherwise one band per screen, always drawn by the screen's own rank (the static split).
    std::vector<cluster::Band> bands;
    bool balanced = false;
};

enum class SetUpOutcome { Ready, HelpShown, Failed };

// Parses the options, loads wall and scene, checks the output paths, opens the context (and
// windows), compiles the raymarcher and makes the screens' targets. Every rank returns the same
// outcome: Failed if any rank failed (rank 0 has printed why), HelpShown after --help.
SetUpOutcome setUpWallSession(const cluster::MpiWorld& world, int argc, char** argv, WallSession& session);

} // namespace aurorawall::app
