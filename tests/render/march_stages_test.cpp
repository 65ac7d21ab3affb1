// The march as a compute shader and as a fragment shader (render/march_shader.h) gives the same
// image on every shipped scene: the same text but for how each stage finds its pixel and writes it.
#include "accuracy/scene_view.h"
#include "components/registry.h"
#include "egl_suite.h"
#include "gl/context.h"
#include "gl/float_target.h"
#include "gl/full_screen_triangle.h"
#include "render/tile_renderer.h"
#include "render/work_counts.h"
#include "scene/scene.h"
#include "scene_samples.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

using namespace aurorawall;

namespace {

const std::string kSource = AURORAWALL_SOURCE_DIR;

class MarchStages : public test::EglSuite<std::string> {};

} // namespace

// On Mesa llvmpipe the two stages compile the shared text alike: the images are bit-identical
// (measured). A GPU's compiler may contract a·b + c into a fused multiply-add in one stage and not
// the other, each such choice moving one rounding by at most u = 2^-24 of its operands; over a march
// whose radiance is a sum of at most a few thousand positive terms (steps, sub-steps, layers) that
// stays below (4096 + 16)·u ≈ 2.5e-4 relative: held as the RMS over the pixels above one 8-bit step
// of the preview, and 10 times that for one pixel, where a float comparison (a skip, a reach test)
// may go the other way and move one sample.
TEST_P(MarchStages, ComputeAndFragmentGiveTheSameImage)
{
    const scene::Scene s = components::loadScene(kSource + "/config/scenes/" + GetParam() + ".toml");
    const accuracy::SceneView view = accuracy::sceneView(s, kSource + "/config/walls/single.toml", {48, 27});
    const io::Image compute = accuracy::renderView(s, view, kSource + "/shaders", 0, render::MarchStage::Compute).image;
    const io::Image fragment = accuracy::renderView(s, view, kSource + "/shaders", 0, render::MarchStage::Fragment).image;
    ASSERT_EQ(compute.rgba.size(), fragment.rgba.size());
    std::vector<glm::dvec3> a, b;
    for (int y = 0; y < compute.height; ++y)
        for (int x = 0; x < compute.width; ++x) {
            a.push_back(accuracy::pixelRadiance(compute, x, y));
            b.push_back(accuracy::pixelRadiance(fragment, x, y));
        }
    const accuracy::RelativeError e = accuracy::relativeError(a, b, 1.0 / (255.0 * s.exposure));
    const bool identical = compute.rgba == fragment.rgba;
    std::printf("%s: compute vs fragment over %zu lit pixels: rms %.3g, max %.3g, %s\n", GetParam().c_str(), e.pixels,
                e.rms, e.max, identical ? "bit-identical" : "not bit-identical");
    if (gl::currentRendererName().rfind("llvmpipe", 0) == 0) {
        EXPECT_TRUE(identical);
    }
    const double bound = (4096 + 16) * std::ldexp(1.0, -24);
    EXPECT_LE(e.rms, bound);
    EXPECT_LE(e.max, 10.0 * bound);
}

INSTANTIATE_TEST_SUITE_P(Config, MarchStages, ::testing::ValuesIn(test::shippedScenes(kSource)),
                         [](const ::testing::TestParamInfo<std::string>& info) { return test::testName(info.param); });

namespace {

struct CountedFrame {
    std::vector<float> counts, work;
    glm::ivec2 size;
};

CountedFrame countedFrame(const std::string& sceneName, render::PixelWork pixelWork = render::PixelWork::Samples)
{
    const scene::Scene s = components::loadScene(kSource + "/config/scenes/" + sceneName + ".toml");
    const accuracy::SceneView view = accuracy::sceneView(s, kSource + "/config/walls/single.toml", {48, 27});
    render::TileRenderer renderer(s, kSource + "/shaders", render::MarchStage::Compute, render::CountWork::Yes,
                                  pixelWork);
    const glm::ivec2 size(48, 27);
    gl::FloatTarget target(size.x, size.y);
    gl::FullScreenTriangle triangle;
    renderer.setFrame(view.frame);
    renderer.renderTile(view.rays, target, triangle);
    return {renderer.workCounts(size), target.readbackWork(0, size.y), size};
}

} // namespace

// The counted march steps are the work the load balancer reads (1 + the aurora's steps), pixel by
// pixel; at most two curtains are evaluated a step; a scene without the aurora counts nothing; and
// a block's largest count is at least its mean.
TEST(WorkCounts, AgreeWithTheWorkTheBalancerReads)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    const CountedFrame f = countedFrame("benchmark-view");
    double steps = 0.0;
    for (int i = 0; i < f.size.x * f.size.y; ++i) {
        EXPECT_EQ(f.counts[4 * i], f.work[i] - 1.0f) << i;
        EXPECT_LE(f.counts[4 * i + 1], 2.0f * f.counts[4 * i]) << i; // at most two candidates a step
        steps += f.counts[4 * i];
    }
    EXPECT_GT(steps, 0.0);
    const render::WorkSummary summary = render::summarizeWork(f.counts, f.size);
    for (int q = 0; q < render::kWorkQuantities; ++q)
        EXPECT_GE(summary.meanBlockMax[q], summary.meanPerPixel[q]) << render::kWorkQuantityNames[q];
    const CountedFrame none = countedFrame("airglow-limb");
    for (float c : none.counts)
        EXPECT_EQ(c, 0.0f);
    EXPECT_THROW(render::TileRenderer(components::loadScene(kSource + "/config/scenes/twilight.toml"),
                                      kSource + "/shaders", render::MarchStage::Fragment, render::CountWork::Yes),
                 std::invalid_argument);
}

// The cost map's measures of a pixel (render/work_counts.h, PixelWork): 1 + its counted texture
// fetches, exactly; and where the context has GL_ARB_shader_clock, its clock cycles: positive and
// finite on every pixel, and the median over the pixels that fetch nothing below the median over
// those that fetch the most (medians: on Mesa's CPU renderers the clock also counts the time the
// operating system took a core away).
TEST(WorkCounts, CostMapMeasures)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    const CountedFrame fetches = countedFrame("benchmark-view", render::PixelWork::TextureFetches);
    for (int i = 0; i < fetches.size.x * fetches.size.y; ++i)
        ASSERT_EQ(fetches.work[i], 1.0f + fetches.counts[4 * i + 3]) << i;
    if (!gl::hasExtension("GL_ARB_shader_clock")) {
        EXPECT_THROW(countedFrame("benchmark-view", render::PixelWork::ShaderClock), std::invalid_argument);
        GTEST_SKIP() << "no GL_ARB_shader_clock on " << gl::currentRendererName();
    }
    const CountedFrame clock = countedFrame("benchmark-view", render::PixelWork::ShaderClock);
    std::vector<float> idle, busy;
    const float most = *std::max_element(fetches.work.begin(), fetches.work.end());
    for (int i = 0; i < clock.size.x * clock.size.y; ++i) {
        ASSERT_TRUE(std::isfinite(clock.work[i]) && clock.work[i] > 0.0f) << i;
        if (fetches.work[i] == 1.0f)
            idle.push_back(clock.work[i]);
        if (fetches.work[i] >= 0.5f * most)
            busy.push_back(clock.work[i]);
    }
    ASSERT_FALSE(idle.empty());
    ASSERT_FALSE(busy.empty());
    const auto median = [](std::vector<float> v) {
        std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
        return v[v.size() / 2];
    };
    EXPECT_LT(median(idle), median(busy));
}
