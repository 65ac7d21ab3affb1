// The airglow on the GPU (EGL; Mesa llvmpipe in CI) against the double-precision CPU reference,
// whose airglow part integrates both exponentials of each layer exactly (adaptive Gauss-Kronrod):
// from orbit at the limb and from the ground toward the horizon, every pixel.
#include "app/accuracy_scene.h"
#include "components/registry.h"
#include "gl/context.h"
#include "render/reference_ray.h"

#include <gtest/gtest.h>

#include <cstdio>

using namespace aurorawall;

namespace {

const std::string kSource = AURORAWALL_SOURCE_DIR;

// The scene's airglow alone with what it is seen through and against (planet, atmosphere): the
// aurora and stars are tested elsewhere.
scene::Scene airglowOnly(const std::string& file)
{
    scene::Scene s = app::withoutUnmodelled(components::loadScene(kSource + "/config/scenes/" + file));
    s.remove("aurora");
    return s;
}

app::RelativeError gpuAgainstReference(const scene::Scene& s)
{
    const app::SceneView view = app::sceneView(s, kSource + "/config/walls/single.toml", {48, 27});
    const io::Image gpu = app::renderView(s, view, kSource + "/shaders", 0).image;
    std::vector<glm::ivec2> pixels;
    std::vector<glm::dvec3> values;
    for (int y = 0; y < gpu.height; ++y)
        for (int x = 0; x < gpu.width; ++x) {
            pixels.emplace_back(x, y);
            values.push_back(app::pixelRadiance(gpu, x, y));
        }
    const render::ReferenceModel model(s, view.frame.timeS, nullptr);
    // Pixels brighter than one 8-bit step of the preview at the scene's exposure.
    return app::relativeError(values, app::referencePixels(model, view, pixels, 2), 1.0 / (255.0 * s.exposure));
}

} // namespace

// Measured: limb rms 6.8e-6, max 3.6e-5; ground rms 3.0e-6, max 3.3e-5 (the float closed forms of the
// airmass work). Held to rms 1e-3 and max 5e-3.
TEST(AirglowOnTheGpu, AgreesWithTheReference)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    for (const char* file : {"airglow-limb.toml", "airglow-ground.toml"}) {
        const app::RelativeError e = gpuAgainstReference(airglowOnly(file));
        std::printf("%s: GPU vs CPU reference over %zu pixels: rms %.3g, max %.3g\n", file, e.pixels, e.rms, e.max);
        EXPECT_GT(e.pixels, 300u) << file;
        EXPECT_LT(e.rms, 1e-3) << file;
        EXPECT_LT(e.max, 5e-3) << file;
    }
}
