// Every shipped scene rendered on this GL device with its defaults, against the double-precision
// CPU reference (render/reference_ray.h) at sampled pixels: the test that vouches for a GPU's
// images (launch/gpu-check runs it on each device). The components the reference does not model
// (stars, planet_texture, sky) are left out of both; every shipped scene keeps lit pixels the
// reference models, so a scene without any, or one the reference refuses, fails.
#include "components/aurora/tools/aurora_accuracy.h"
#include "components/registry.h"
#include "components/roles/curtain_detail.h"
#include "egl_suite.h"
#include "gl/context.h"
#include "render/reference_ray.h"
#include "scene/scene.h"
#include "scene_samples.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

using namespace aurorawall;

namespace {

const std::string kSource = AURORAWALL_SOURCE_DIR;

class ShippedScene : public test::EglSuite<std::string> {};

} // namespace

// The tolerance is the accuracy the defaults are chosen for (docs/ACCURACY.md): 1% of the radiance,
// whatever the device, as the RMS over the sampled lit pixels and at each of them: since the exact
// sub-step flux is the default, no pixel at a curtain's edge errs by more than the approximations left
// (a run's emission at its mean position, the tables' interpolation), well below it. Float rounding is
// far below it too (a march of at most a few hundred steps: (n + 16)·2^-24 < 3e-5). Pixels darker than
// one 8-bit step of the preview at the scene's exposure are not compared.
TEST_P(ShippedScene, DefaultsAgreeWithTheCpuReference)
{
    scene::Scene s = scene::withoutUnmodelled(components::loadScene(kSource + "/config/scenes/" + GetParam() + ".toml"));
    const accuracy::SceneView view = accuracy::sceneView(s, kSource + "/config/walls/single.toml", {64, 36});
    const io::Image gpu = accuracy::renderView(s, view, kSource + "/shaders", 0).image;
    const double floor = 1.0 / (255.0 * s.exposure);
    const std::vector<glm::ivec2> pixels = test::litPixels(gpu, floor, 12);
    ASSERT_FALSE(pixels.empty()) << GetParam() << ": no lit pixel once stars, sky and night lights are left out";
    const std::shared_ptr<const components::roles::FluxFrames> frames = components::roles::curtainDetailFrames(s);
    std::unique_ptr<render::ReferenceModel> model;
    try {
        model = std::make_unique<render::ReferenceModel>(s, view.frame.timeS,
                                                         components::roles::curtainDetailData(frames.get()));
    } catch (const std::invalid_argument& e) {
        FAIL() << GetParam() << ": the CPU reference does not model it (" << e.what() << ")";
    }
    const std::vector<glm::dvec3> reference = accuracy::referencePixels(*model, view, pixels, 2);
    std::vector<glm::dvec3> values;
    for (const glm::ivec2& p : pixels)
        values.push_back(accuracy::pixelRadiance(gpu, p.x, p.y));
    const accuracy::RelativeError e = accuracy::relativeError(values, reference, floor);
    std::printf("%s: GPU defaults vs CPU reference at %zu lit pixels: rms %.3g, max %.3g\n", GetParam().c_str(),
                e.pixels, e.rms, e.max);
    EXPECT_LT(e.rms, 1e-2);
    EXPECT_LT(e.max, 1e-2);
}

INSTANTIATE_TEST_SUITE_P(Config, ShippedScene, ::testing::ValuesIn(test::shippedScenes(kSource)),
                         [](const ::testing::TestParamInfo<std::string>& info) { return test::testName(info.param); });
