// Empty-space skipping: on every camera preset, the image with
// skip_empty_space = yes equals the naive march (no) with the same step. A skip ends where the
// footprint map's conservative distance allows, so it never crosses an emitting region, and it
// jumps over whole steps of the naive march's grid, so the samples it takes are the naive march's.
// So the image is also the same whether the CPU or the GPU built the map.
#include "accuracy/scene_view.h"
#include "egl_suite.h"
#include "gl/context.h"
#include "components/aurora/aurora.h"
#include "components/fluid_detail/fluid_detail.h"
#include "components/registry.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <cstdio>

using namespace aurorawall;

namespace {

const std::string kSource = AURORAWALL_SOURCE_DIR;

struct Difference {
    accuracy::RelativeError error;
    double skipMs = 0.0, naiveMs = 0.0;
};

// The preset at 64x36 (field of view of config/walls/single.toml), frame 0, with `stepKm`, skipping
// on and off: per-pixel relative difference over the pixels above one 8-bit step of the preview.
Difference skipAgainstNaive(const std::string& preset, double stepKm)
{
    scene::Scene s = components::loadScene(kSource + "/config/scenes/" + preset);
    s.settings<components::aurora::Settings>().stepKm = stepKm;
    const accuracy::SceneView view = accuracy::sceneView(s, kSource + "/config/walls/single.toml", {64, 36});
    s.settings<components::aurora::Settings>().skipEmptySpace = true;
    const accuracy::TimedRender skip = accuracy::renderView(s, view, kSource + "/shaders", 1);
    s.settings<components::aurora::Settings>().skipEmptySpace = false;
    const accuracy::TimedRender naive = accuracy::renderView(s, view, kSource + "/shaders", 1);
    std::vector<glm::dvec3> a, b;
    for (int y = 0; y < 36; ++y)
        for (int x = 0; x < 64; ++x) {
            a.push_back(accuracy::pixelRadiance(skip.image, x, y));
            b.push_back(accuracy::pixelRadiance(naive.image, x, y));
        }
    Difference d{accuracy::relativeError(a, b, 1.0 / (255.0 * s.exposure)), skip.msPerFrame, naive.msPerFrame};
    std::printf("%-20s step %.2f km: %zu pixels, rms %.3g, max %.3g; %.0f ms skipping, %.0f ms naive\n",
                preset.c_str(), stepKm, d.error.pixels, d.error.rms, d.error.max, d.skipMs, d.naiveMs);
    return d;
}

class Skipping : public test::EglSuite<const char*> {};

} // namespace

// The skipping march lands on the naive march's grid and leaves out only samples that emit nothing,
// so the two images are equal, not just close, on every preset and at every step.
TEST_P(Skipping, EqualsTheNaiveMarch)
{
    for (double stepKm : {0.5, 2.0}) {
        const Difference d = skipAgainstNaive(GetParam(), stepKm);
        EXPECT_GT(d.error.pixels, 0u);
        EXPECT_EQ(d.error.max, 0.0) << "step " << stepKm << " km";
    }
}

// Both maps are conservative and name a nearest point from which the march finds the same exact
// curtain coordinates, so the march takes the same samples with either map: equal images.
TEST_P(Skipping, MapBuiltOnTheGpuGivesTheSameImage)
{
    scene::Scene s = components::loadScene(kSource + "/config/scenes/" + GetParam());
    const accuracy::SceneView view = accuracy::sceneView(s, kSource + "/config/walls/single.toml", {64, 36});
    auto& aurora = s.settings<components::aurora::Settings>();
    aurora.footprintMapBuild = components::aurora::MapBuilder::Cpu;
    const accuracy::TimedRender cpu = accuracy::renderView(s, view, kSource + "/shaders", 0);
    aurora.footprintMapBuild = components::aurora::MapBuilder::Gpu;
    const accuracy::TimedRender gpu = accuracy::renderView(s, view, kSource + "/shaders", 0);
    size_t lit = 0;
    for (int y = 0; y < 36; ++y)
        for (int x = 0; x < 64; ++x) {
            const glm::dvec3 a = accuracy::pixelRadiance(cpu.image, x, y), b = accuracy::pixelRadiance(gpu.image, x, y);
            ASSERT_EQ(a, b) << "pixel " << x << "," << y;
            lit += a != glm::dvec3(0.0);
        }
    EXPECT_GT(lit, 0u);
}

INSTANTIATE_TEST_SUITE_P(Presets, Skipping,
                         ::testing::Values("benchmark-view.toml", "ground-65n.toml", "low-orbit.toml", "far-space.toml",
                                           "substorm.toml"));
