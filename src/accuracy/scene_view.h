#pragma once
// What the accuracy runs of a scene share (`aurorawall accuracy --scene FILE` and the components'
// tables, components/tools.h): a small view of the scene, timed renders of it on one headless EGL
// context, relative errors, the double-precision CPU reference (render/reference_ray.h) at chosen
// pixels. Also the tools of tests/render/reference_ray_test.cpp and skipping_test.cpp.
#include "cluster/frame_state.h"
#include "gl/context.h"
#include "io/image.h"
#include "render/march_shader.h"
#include "render/reference_ray.h"
#include "scene/scene.h"
#include "wall/tile_rays.h"
#include "wall/wall.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace aurorawall::accuracy {

// One small view of a scene: the wall file's single-screen equivalent with the same physical screen
// and eye (so the same field of view) at sizePx pixels, and the scene's frame `frame` as `render`
// draws it (the master clock's frame: the scene's start time plus frame time steps, the camera moved
// along its path for that long; frame 0 is the scene's start time and camera).
struct SceneView {
    wall::Wall wall;
    wall::TileRays rays;
    cluster::FrameState frame;
};
SceneView sceneView(const scene::Scene& scene, const std::string& wallFile, glm::ivec2 sizePx, long long frame = 0);

// The view's pixel (x, y) (x right, y down from the top-left) as a unit direction in the planet
// frame, in double: the direction through the pixel centre (tile_rays.h) rotated as TileRenderer does.
glm::dvec3 pixelDirection(const SceneView& view, int x, int y);

// A render of the view and its time per frame: `runs` frames after one warm-up frame, each
// setFrame + renderTile + glFinish timed on the CPU clock (llvmpipe's timer queries are wrong);
// msPerFrame is the median. Needs a current GL context.
struct TimedRender {
    io::Image image;
    double msPerFrame = 0.0;
};
TimedRender renderView(const scene::Scene& scene, const SceneView& view, const std::string& shaderDir, int runs);
// The same with the march in the given shader stage (the one above: the device's preferred stage).
TimedRender renderView(const scene::Scene& scene, const SceneView& view, const std::string& shaderDir, int runs,
                       render::MarchStage stage);

// Per-pixel relative error e = |a - r| / |r| (Euclidean norm of linear RGB) over the pixels whose
// reference radiance |r| is at least `floor`: RMS and maximum of e, and how many pixels.
struct RelativeError {
    double rms = 0.0;
    double max = 0.0;
    size_t pixels = 0;
};
RelativeError relativeError(const std::vector<glm::dvec3>& values, const std::vector<glm::dvec3>& reference,
                            double floor);
glm::dvec3 pixelRadiance(const io::Image& image, int x, int y);

// The CPU reference at the given pixels, on `threads` threads.
std::vector<glm::dvec3> referencePixels(const render::ReferenceModel& model, const SceneView& view,
                                        const std::vector<glm::ivec2>& pixels, int threads);

// Opens the headless EGL context of the accuracy runs and prints "renderer: NAME, GL VERSION". With a
// view size (--size), first throws std::runtime_error naming it where the device cannot draw that large.
std::unique_ptr<gl::Context> openAccuracyContext(std::ostream& out, glm::ivec2 sizePx = glm::ivec2(0));

struct SceneAccuracySettings {
    std::string sceneFile;
    std::string wallFile;         // its single-screen equivalent sets the field of view; empty: config/walls/single.toml
    glm::ivec2 sizePx{320, 180};  // the render size
    int pixels = 48;              // pixels of the CPU reference
    int runs = 3;                 // timed frames per setting after one warm-up (the median is reported)
    long long frame = 0;          // the scene's frame (sceneView)
    int threads = 2;              // CPU reference threads
    double referenceStepKm = 0.05; // CPU reference step where a curtain is in reach
    bool featureCosts = false;    // the frame time of each feature toggled alone instead of the knobs
    bool workStats = false;       // the march's work per pixel and per 8x4 block instead of the knobs
    int views = 0;                // > 0: the default's error at this many views drawn at random instead of the knobs
    std::uint64_t seed = 1;       // the views' seed (random_views.h)
};

} // namespace aurorawall::accuracy
