#pragma once
// The aurora's sweep of `aurorawall accuracy --scene FILE` (components/tools.h): error against run
// time of the march's quality knobs (with the other listed components' knobs, components::SweepKnob)
// and the cost of each feature (Lawlor & Genetti's table 2), on one headless EGL context in one
// process (no MPI), with the means of accuracy/scene_view.h.
#include "accuracy/random_views.h"
#include "accuracy/scene_view.h"
#include "scene/scene.h"

#include <functional>
#include <iosfwd>

namespace aurorawall::components::aurora::tools {

// The GPU reference's settings: 0.25 km steps, the finest tables, footprint map and polylines of the
// knob ranges, and the finest value of each other component's knob that refines only the GPU's
// approximation (SweepKnob::refinesModel false, e.g. a particle push's steps per cell). With
// empty-space skipping, which gives the naive march's image (tests/render/skipping_test.cpp) in a
// fraction of its loop iterations: llvmpipe ends every loop of a shader invocation after 65535
// iterations of all its loops together, which the naive 0.25 km march reaches on long rays near
// curtains.
void applyFinestSettings(scene::Scene& scene);

// The error of the scene's settings at `settings.views` views drawn at random from `settings.seed`
// (accuracy/random_views.h), the kinds of view in turn from `start` (the scene's view at its frame),
// over the pixels where the aurora gives at least half the radiance at those settings: against the
// GPU render at the finest settings at every such pixel, and against the CPU reference at
// `settings.pixels` of them, evenly spaced. A kind's view is drawn again (up to 200 times) until it
// has 16 such pixels. `scene` lists only what the CPU reference models (scene::withoutUnmodelled).
// `measured` is called after each view. Needs a current GL context.
struct ViewError {
    accuracy::ViewKind kind = accuracy::ViewKind::Ground;
    cluster::FrameState frame;  // the camera and the time drawn
    size_t auroraPixels = 0;    // 0: no view of this kind with 16 such pixels was found
    accuracy::RelativeError gpu, cpu;
};
void measureViews(const scene::Scene& scene, const accuracy::SceneView& start, const std::string& shaderDir,
                  const accuracy::SceneAccuracySettings& settings, const std::function<void(const ViewError&)>& measured);

// The knob table (or, with featureCosts, the feature costs; with workStats, the work counts; with
// views, the views' errors of measureViews as CSV) on `out`. Throws when a file cannot be read or is malformed, and when no GL context or shader can be made.
void runSceneAccuracy(const accuracy::SceneAccuracySettings& settings, std::ostream& out);

} // namespace aurorawall::components::aurora::tools
