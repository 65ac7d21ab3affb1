// The plasma box on the GPU against the double-precision CPU reference (box_reference.h), which
// reads the same frames and integrates their column exactly (tests/app/data/plasma-box-side.toml:
// the box's bands seen from the side, across the field).
#include "app/accuracy_scene.h"
#include "components/plasma/box_reference.h"
#include "components/plasma/plasma.h"
#include "components/registry.h"
#include "gl/context.h"
#include "render/reference_ray.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>
#include <sstream>

using namespace aurorawall;

namespace {

const std::string kSource = AURORAWALL_SOURCE_DIR;

// The `count` brightest pixels of an image: on the box.
std::vector<glm::ivec2> brightestPixels(const io::Image& image, size_t count)
{
    std::vector<glm::ivec2> pixels;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            pixels.emplace_back(x, y);
    std::sort(pixels.begin(), pixels.end(), [&](glm::ivec2 a, glm::ivec2 b) {
        return glm::length(app::pixelRadiance(image, a.x, a.y)) > glm::length(app::pixelRadiance(image, b.x, b.y));
    });
    pixels.resize(std::min(count, pixels.size()));
    return pixels;
}

struct Comparison {
    app::RelativeError error, otherFrame;
};

// The scene rendered with `stepsPerCell` against the reference at the view's time and at the time one
// frame earlier.
Comparison compare(int stepsPerCell)
{
    scene::Scene s = app::withoutUnmodelled(components::loadScene(kSource + "/tests/app/data/plasma-box-side.toml"));
    app::applyFinestSettings(s);
    auto& plasma = s.settings<components::plasma::Settings>();
    plasma.boxStepsPerCell = stepsPerCell;
    const app::SceneView view = app::sceneView(s, kSource + "/config/walls/single.toml", {64, 36});
    const io::Image gpu = app::renderView(s, view, kSource + "/shaders", 0).image;
    const std::vector<glm::ivec2> pixels = brightestPixels(gpu, 32);
    std::vector<glm::dvec3> values;
    for (const glm::ivec2& p : pixels)
        values.push_back(app::pixelRadiance(gpu, p.x, p.y));
    const double floor = 1.0 / (255.0 * s.exposure);
    const std::shared_ptr<const fluid::FluxFrames> strip = components::plasma::component().referenceFrames(s);
    const render::ReferenceModel model(s, view.frame.timeS, strip.get());
    const double frameS = plasma.boxPlayS / (plasma.boxFrames - 1);
    const render::ReferenceModel earlier(s, view.frame.timeS - frameS, strip.get());
    return {app::relativeError(values, app::referencePixels(model, view, pixels, 2), floor),
            app::relativeError(values, app::referencePixels(earlier, view, pixels, 2), floor)};
}

} // namespace

// Tolerances: measured at the 32 brightest pixels (the crests of the bands), held to about three
// times. 16 steps per cell: RMS 5.9e-7, max 1.2e-6, float round-off of the march's 256 lookups (the
// texture's filtering and the float camera offset included); held to 2e-6 and 4e-6. 2 steps per
// cell (the default): RMS 1.7e-5, max 5.4e-5, the midpoint rule's error on the bands; held to 5e-5
// and 1.5e-4, and at least 5 times the finer march's RMS (29 measured): the knob reaches the shader.
// The reference one frame (20 steps) earlier is off by RMS 5.6e-2, held above 1e-2: the comparison
// sees the frame.
TEST(PlasmaBoxOnTheGpu, AgreesWithTheReference)
{
    const std::unique_ptr<gl::Context> context = gl::createContext(gl::Backend::Egl);
    const Comparison fine = compare(16), coarse = compare(2);
    std::printf("plasma box: GPU vs CPU reference at the %zu brightest pixels: 16 steps per cell rms %.3g, max "
                "%.3g; 2 steps per cell rms %.3g, max %.3g; against the frame before: rms %.3g\n",
                fine.error.pixels, fine.error.rms, fine.error.max, coarse.error.rms, coarse.error.max,
                fine.otherFrame.rms);
    EXPECT_EQ(fine.error.pixels, 32u);
    EXPECT_LT(fine.error.rms, 2e-6);
    EXPECT_LT(fine.error.max, 4e-6);
    EXPECT_LT(coarse.error.rms, 5e-5);
    EXPECT_LT(coarse.error.max, 1.5e-4);
    EXPECT_GT(coarse.error.rms, 5.0 * fine.error.rms);
    EXPECT_GT(fine.otherFrame.rms, 1e-2);
}

// `aurorawall accuracy --scene` on the box scene (32x18 px, one timed frame): the reference is made
// (the box and the strip's frames), and the table has a row per box_steps_per_cell; 16 steps per
// cell is the GPU reference's own setting (no difference), and the coarser marches are off from it
// by more the fewer their steps (measured over the lit pixels: RMS 9.5e-5, 1.2e-5, 2.9e-6 for 1, 2
// and 4 steps per cell; 1 step per cell held above 1e-5).
TEST(PlasmaBoxOnTheGpu, AccuracyTableHasTheBoxKnob)
{
    app::SceneAccuracySettings settings;
    settings.sceneFile = kSource + "/tests/app/data/plasma-box-side.toml";
    settings.wallFile = kSource + "/config/walls/single.toml";
    settings.sizePx = {32, 18};
    settings.pixels = 16;
    settings.runs = 1;
    std::ostringstream out;
    app::runSceneAccuracy(settings, out);
    std::map<int, double> rmsGpu; // steps per cell -> rms_rel_gpu
    std::istringstream lines(out.str());
    for (std::string line; std::getline(lines, line);) {
        std::istringstream words(line);
        std::string knob;
        int steps = 0;
        double rms = 0.0;
        if (words >> knob >> steps >> rms && knob == "box_steps_per_cell")
            rmsGpu[steps] = rms;
    }
    std::printf("%s", out.str().c_str());
    ASSERT_EQ(rmsGpu.size(), 5u) << out.str();
    EXPECT_EQ(rmsGpu[16], 0.0);
    EXPECT_GT(rmsGpu[1], 1e-5);
    EXPECT_GT(rmsGpu[1], rmsGpu[2]);
    EXPECT_GT(rmsGpu[2], rmsGpu[4]);
}
