// The airglow on the GPU (EGL; Mesa llvmpipe in CI) against the double-precision CPU reference,
// whose airglow part integrates both exponentials of each layer exactly (adaptive Gauss-Kronrod):
// from orbit at the limb and from the ground toward the horizon, every pixel.
#include "components/airglow/airglow.h"
#include "components/atmosphere/atmosphere.h"
#include "components/aurora/tools/aurora_accuracy.h"
#include "components/registry.h"
#include "gl/context.h"
#include "render/float_bounds.h"
#include "render/reference_ray.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace aurorawall;
using test::glslExpError;
using test::kUnitRoundoff;

namespace {

const std::string kSource = AURORAWALL_SOURCE_DIR;

// The scene's airglow alone with what it is seen through and against (planet, atmosphere): the
// aurora and stars are tested elsewhere.
scene::Scene airglowOnly(const std::string& file)
{
    scene::Scene s = scene::withoutUnmodelled(components::loadScene(kSource + "/config/scenes/" + file));
    s.remove("aurora");
    return s;
}

// Every pixel brighter than one 8-bit step of the preview at the scene's exposure against its own
// bound. The pixel holds the atmosphere's glow G = g(1 − T) (T its transmittance, g the glow) and
// each layer's A·T, A = a(U_u − U_l) the layer's column (two exponential columns U of scale heights
// H_u and H_l = H_u/2). The reference gives G (without the airglow) and A (without the atmosphere),
// hence T = 1 − G/g and the optical depth τ = −ln T. Float allows:
// - A: each U by its float error (test::floatAirmassError, w ≤ 40: the layers end at 40 H_u) and by
//   the closed form's own (test::closedFormAirmassError; its safe form only on rays that graze a
//   layer's top, where the column is e^-39 of its base's), amplified by the difference's condition
//   (U_u + U_l)/(U_u − U_l), at most (1 + 2^-½)/(1 − 2^-½) = 5.8 (U_l/U_u is 1/2 on a ray that
//   leaves the base and 2^-½ on one that grazes it); 4 roundings more for the colour, T and the sum;
// - T = e^-τ: τ times the airmass's error (its float error with w ≤ 9.4, the atmosphere's 75 km
//   top over its 8 km scale height, and the closed form's), and exp's (6 + 4τ)u; on A·T and on g·T,
//   which G holds, with 2 roundings of G;
// - the ray itself rounded to float: test::rayRoundingBound.
test::BoundedError gpuAgainstReference(const scene::Scene& s)
{
    const accuracy::SceneView view = accuracy::sceneView(s, kSource + "/config/walls/single.toml", {48, 27});
    const io::Image gpu = accuracy::renderView(s, view, kSource + "/shaders", 0).image;
    scene::Scene withoutAirglow = s, withoutAtmosphere = s;
    withoutAirglow.remove("airglow");
    withoutAtmosphere.remove("atmosphere");
    const render::ReferenceModel model(s, view.frame.timeS, {});
    const render::ReferenceModel glowModel(withoutAirglow, view.frame.timeS, {});
    const render::ReferenceModel airglowModel(withoutAtmosphere, view.frame.timeS, {});
    const auto& air = s.settings<components::atmosphere::Settings>();
    const double u = kUnitRoundoff, R = s.planetRadiusKm;
    double layerError = 0.0; // ε_U plus the closed form's, the worst layer
    for (const components::airglow::Layer& l : s.settings<components::airglow::Settings>().layers) {
        const components::airglow::LayerProfile p = components::airglow::layerProfile(l);
        layerError = std::max(layerError, test::floatAirmassError(40.0) +
                                              test::closedFormAirmassError(p.lowerScaleHeightKm, R + p.baseKm));
    }
    const double condition = (1.0 + std::sqrt(0.5)) / (1.0 - std::sqrt(0.5));
    const double airmassError = test::floatAirmassError(air.topKm / air.scaleHeightKm) +
                                test::closedFormAirmassError(air.scaleHeightKm, R);
    const double floor = 1.0 / (255.0 * s.exposure);
    test::BoundedError b;
    for (int y = 0; y < gpu.height; ++y)
        for (int x = 0; x < gpu.width; ++x) {
            const glm::dvec3 d = accuracy::pixelDirection(view, x, y), o = view.frame.cameraPositionKm;
            const glm::dvec3 reference = model.radiance(o, d);
            const double r = glm::length(reference);
            if (!(r >= floor))
                continue;
            const glm::dvec3 glow = glowModel.radiance(o, d), airglow = airglowModel.radiance(o, d);
            glm::dvec3 channels(0.0);
            for (int c = 0; c < 3; ++c) {
                const double T = std::clamp(1.0 - glow[c] / air.skyGlow[c], 1e-300, 1.0), tau = -std::log(T);
                const double transmittanceError = tau * airmassError + glslExpError(tau);
                channels[c] = airglow[c] * T * (condition * layerError + 4.0 * u + transmittanceError) +
                              air.skyGlow[c] * T * transmittanceError + 2.0 * u * glow[c];
            }
            const double bound = (glm::length(channels) + test::rayRoundingBound(model, view, x, y)) / r;
            b.add(glm::length(accuracy::pixelRadiance(gpu, x, y) - reference) / r, bound);
        }
    return b;
}

} // namespace

// Each pixel's error within the bound float allows it (gpuAgainstReference); measured (llvmpipe):
// limb RMS 6.8e-6, max 3.6e-5; ground RMS 3.0e-6, max 3.3e-5.
TEST(AirglowOnTheGpu, AgreesWithTheReference)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    for (const char* file : {"airglow-limb.toml", "airglow-ground.toml"}) {
        const test::BoundedError e = gpuAgainstReference(airglowOnly(file));
        std::printf("%s: GPU vs CPU reference over %zu pixels: rms %.3g, max %.3g; the bound's rms %.3g; "
                    "largest error / bound %.3g\n",
                    file, e.pixels, e.rms, e.max, e.rmsBound, e.worstRatio);
        EXPECT_GT(e.pixels, 300u) << file;
        EXPECT_LT(e.worstRatio, 1.0) << file;
        EXPECT_LT(e.rms, e.rmsBound) << file;
    }
}
