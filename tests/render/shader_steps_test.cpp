// The march in double (ReferenceSettings::shaderSteps: the aurora's shader text compiled as C++ and given
// the GPU's data, src/components/aurora/aurora_march.h; the atmosphere's closed-form airmass) against the
// fine CPU reference (src/render/reference_ray.h), on the substorm scene at the renderer's finest settings.
// No float is left between them: what differs is the march's discretization (its steps, sub-steps and
// tables), and it shrinks as they are refined. No GL context.
#include "common/glsl.h"
#include "components/aurora/aurora.h"
#include "components/aurora/curtain_model.h"
#include "components/aurora/tools/aurora_accuracy.h"
#include "components/fluid_detail/curtain_detail.h"
#include "components/fluid_detail/simulation/curtain_detail.h"
#include "components/plasma/plasma.h"
#include "components/plasma/sheet_frames.h"
#include "components/registry.h"
#include "components/roles/curtain_detail.h"
#include "render/reference_ray.h"
#include "scene/scene.h"
#include "scene_samples.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

using namespace aurorawall;
using aurorawall::components::roles::curtainDetailData;

namespace {

const std::string kSource = AURORAWALL_SOURCE_DIR;
constexpr int kWidth = 64, kHeight = 36;

class ShaderSteps : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        scene_ = new scene::Scene(scene::withoutUnmodelled(components::loadScene(kSource + "/config/scenes/substorm.toml")));
        components::aurora::tools::applyFinestSettings(*scene_);
        view_ = new accuracy::SceneView(accuracy::sceneView(*scene_, kSource + "/config/walls/single.toml", {kWidth, kHeight}));
        frames_ = new components::roles::FluxFrames(components::fluid_detail::simulation::simulateCurtainDetail(
            components::fluid_detail::curtainDetailSpec(scene_->settings<components::fluid_detail::Settings>())));
    }
    static void TearDownTestSuite()
    {
        delete frames_;
        delete view_;
        delete scene_;
    }
    static render::ReferenceModel march(const scene::Scene& s)
    {
        render::ReferenceSettings settings;
        settings.shaderSteps = true;
        return render::ReferenceModel(s, view_->frame.timeS, curtainDetailData(frames_), settings);
    }
    // One 8-bit step of the linear preview at the scene's exposure.
    static double floor() { return 1.0 / (255.0 * scene_->exposure); }

    static scene::Scene* scene_;
    static accuracy::SceneView* view_;
    static components::roles::FluxFrames* frames_;
};

scene::Scene* ShaderSteps::scene_ = nullptr;
accuracy::SceneView* ShaderSteps::view_ = nullptr;
components::roles::FluxFrames* ShaderSteps::frames_ = nullptr;

// Scene s with the aurora's march refined: half the step, sub-steps and altitude step of the emission rows,
// and 4x their energies.
scene::Scene refinedMarch(const scene::Scene& s)
{
    scene::Scene refined = s;
    auto& aurora = refined.settings<components::aurora::Settings>();
    aurora.stepKm /= 2.0;
    aurora.resolveKm /= 2.0;
    aurora.resolveCells /= 2.0;
    aurora.tableAltitudeStepKm /= 2.0;
    aurora.tableEnergyCount *= 4;
    return refined;
}

// The march (coarse) and the refined march (fine) against the reference at `pixels` of `view`, relative
// errors above `floor`: the march's largest below `maxError`, the refined march's below `share` of it.
void expectTheDiscretization(const std::string& name, const render::ReferenceModel& coarse,
                             const render::ReferenceModel& fine, const render::ReferenceModel& reference,
                             const accuracy::SceneView& view, const std::vector<glm::ivec2>& pixels, double floor,
                             double maxError, double share)
{
    SCOPED_TRACE(name);
    const std::vector<glm::dvec3> r = accuracy::referencePixels(reference, view, pixels, 2);
    const accuracy::RelativeError e = accuracy::relativeError(accuracy::referencePixels(coarse, view, pixels, 2), r, floor);
    const accuracy::RelativeError eFine = accuracy::relativeError(accuracy::referencePixels(fine, view, pixels, 2), r, floor);
    std::printf("%s: march in double vs CPU reference at %zu pixels: rms %.3g, max %.3g; refined march: rms %.3g, max %.3g\n",
                name.c_str(), e.pixels, e.rms, e.max, eFine.rms, eFine.max);
    EXPECT_EQ(e.pixels, pixels.size());
    EXPECT_LT(e.max, maxError);
    EXPECT_LT(eFine.max, share * e.max);
}

} // namespace

// At the pixels of tests/render/reference_ray_test.cpp (16 lit pixels of the march's image, most lit by the
// sky's glow) and at 16 of the brightest 64 (the aurora). Measured: RMS 3.5e-5, max 1.1e-4 and RMS 2.7e-4,
// max 6.1e-4: the march's discretization, held to 1e-3. It is discretization because it converges: the
// march with half the step, sub-steps and altitude step of the emission rows and 4x their energies lies
// 3.6e-5 and 1.2e-4 (max) from the reference; held to half the finest settings' difference.
TEST_F(ShaderSteps, DiffersFromTheReferenceByItsDiscretization)
{
    const render::ReferenceModel coarse = march(*scene_);
    const std::vector<glm::dvec3> image = test::referenceImage(coarse, *view_, kWidth, kHeight);
    std::vector<glm::ivec2> brightest;
    const std::vector<glm::ivec2> brightest64 = test::brightestPixels(image, kWidth, 64);
    for (size_t i = 0; i < 16; ++i)
        brightest.push_back(brightest64[4 * i]);

    const scene::Scene refined = refinedMarch(*scene_); // outlives the model, which refers to it
    const render::ReferenceModel fine = march(refined);
    const render::ReferenceModel reference(*scene_, view_->frame.timeS, curtainDetailData(frames_));
    expectTheDiscretization("substorm, lit pixels", coarse, fine, reference, *view_,
                            test::litPixels(image, kWidth, floor(), 16), floor(), 1e-3, 0.5);
    expectTheDiscretization("substorm, brightest pixels", coarse, fine, reference, *view_, brightest, floor(), 1e-3, 0.5);
}

// The plasma's electron strip (tests/app/data/plasma-seam.toml at the finest settings) at the 16 brightest
// pixels of the march's image, those of tests/components/plasma/plasma_gl_test.cpp. Measured: RMS 3.5e-4,
// max 6.1e-4 (the strip's one-texel edges), held to 5e-3; refined as above, max 2.7e-4: held to 3/4 of it.
TEST(ShaderStepsOnPlasma, DifferFromTheReferenceByTheirDiscretization)
{
    scene::Scene s = scene::withoutUnmodelled(components::loadScene(kSource + "/tests/app/data/plasma-seam.toml"));
    components::aurora::tools::applyFinestSettings(s);
    const accuracy::SceneView view = accuracy::sceneView(s, kSource + "/config/walls/single.toml", {kWidth, kHeight});
    const components::roles::FluxFrames frames =
        components::plasma::simulateSheetFrames(components::plasma::sheetFramesSpec(s.settings<components::plasma::Settings>()));
    render::ReferenceSettings settings;
    settings.shaderSteps = true;
    const render::ReferenceModel coarse(s, view.frame.timeS, curtainDetailData(&frames), settings);
    const std::vector<glm::ivec2> pixels = test::brightestPixels(test::referenceImage(coarse, view, kWidth, kHeight), kWidth, 16);
    const scene::Scene refined = refinedMarch(s);
    const render::ReferenceModel fine(refined, view.frame.timeS, curtainDetailData(&frames), settings);
    const render::ReferenceModel reference(s, view.frame.timeS, curtainDetailData(&frames));
    expectTheDiscretization("plasma", coarse, fine, reference, view, pixels, 1.0 / (255.0 * s.exposure), 5e-3, 0.75);
}

// The plasma box's scene from 96.6 km up, inside the auroral layer, looking along its weak arc (a view drawn at
// random): the arc's detail is the plasma's strip of sheets, and a 2 km step's piece can run along the curtain
// through a whole sheet between two ends where the flux is nil: judged by its ends alone, the end-point rule
// looks exact there and would drop the sheet (RMS 1.9e-2, max 6.0e-2 where it did). The march in double
// against the CPU reference at the arc's pixels (relative errors above a thousandth of the brightest):
// measured RMS 5.9e-4, max 1.8e-3, held to RMS 1e-3 and to the 1% goal at every pixel.
TEST(ShaderStepsOnPlasmaBox, PiecesThroughWholeSheetsKeepTheirEmission)
{
    scene::Scene s = scene::withoutUnmodelled(components::loadScene(kSource + "/config/scenes/plasma-box.toml"));
    s.startTimeS = 567.42;
    accuracy::SceneView view = accuracy::sceneView(s, kSource + "/config/walls/single.toml", {160, 90});
    test::placeCamera(view.frame, glm::dvec3(-1928.276597, -1456.786772, 5999.091053),
                      glm::normalize(glm::dvec3(-0.566486, 0.629386, 0.531946)),
                      glm::normalize(glm::dvec3(0.060628, 0.675591, -0.734779)));
    const components::roles::FluxFrames frames =
        components::plasma::simulateSheetFrames(components::plasma::sheetFramesSpec(s.settings<components::plasma::Settings>()));
    render::ReferenceSettings settings;
    settings.shaderSteps = true;
    const render::ReferenceModel march(s, view.frame.timeS, curtainDetailData(&frames), settings);
    const render::ReferenceModel reference(s, view.frame.timeS, curtainDetailData(&frames));
    std::vector<glm::ivec2> pixels;
    for (int y = 0; y < 7; ++y)
        for (int x = 54; x < 66; ++x)
            pixels.emplace_back(x, y);
    const std::vector<glm::dvec3> r = accuracy::referencePixels(reference, view, pixels, 2);
    double brightest = 0.0;
    for (const glm::dvec3& v : r)
        brightest = std::max(brightest, glm::length(v));
    const accuracy::RelativeError e =
        accuracy::relativeError(accuracy::referencePixels(march, view, pixels, 2), r, 1e-3 * brightest);
    std::printf("plasma box, inside the layer along the arc: march in double vs CPU reference at %zu pixels: rms %.3g, max %.3g\n",
                e.pixels, e.rms, e.max);
    EXPECT_GE(e.pixels, 60u) << "the view shows the arc";
    EXPECT_LT(e.rms, 1e-3);
    EXPECT_LT(e.max, 1e-2);
}

// A smooth curtain ends in a round cap: beyond its end the column fades as the profile does across it, so the
// flux at a distance ρ beyond the end, in any direction there, is the flux ρ across from its centre line,
// exp(−ρ² / 2σ²). Vertical rays from 400 km down the quiet arc (σ = 3 km), at 0.5σ to 2σ beyond its east end
// (straight out along its last segment and 45° to either side) and across its middle: in the CPU reference
// the same radiance, but for the sphere's curvature over ρ, (ρ / R)² ~ 1e-6 (its 0.05 km column steps are the
// same on each ray); held to 1e-4. The march in double reads the polyline and its normals in float, as the GPU
// does, which places u within 32 u R of the double one (aurora_float_bound.h) and moves the flux by ρ du / σ²:
// measured 2e-4 to 4e-4, held to that bound.
TEST(CurtainEnds, FadeBeyondTheEndAsTheProfileDoesAcross)
{
    scene::Scene s = scene::withoutUnmodelled(components::loadScene(kSource + "/config/scenes/quiet-arc.toml"));
    const double R = s.planetRadiusKm;
    const auto& aurora = s.settings<components::aurora::Settings>();
    const components::aurora::CurtainModel curtains(aurora, R, nullptr);
    const components::aurora::physics::CurtainPolyline line = curtains.at(s.startTimeS).front().polyline;
    const double sigmaKm = 0.5 * aurora.curtains.front().thicknessKm;
    // A point `km` from unit vector p along the unit tangent direction `towards`, on the sphere.
    auto moved = [R](glm::dvec3 p, glm::dvec3 towards, double km) {
        return std::cos(km / R) * p + std::sin(km / R) * towards;
    };
    const size_t last = line.points.size() - 1;
    const glm::dvec3 end = line.points[last];
    const glm::dvec3 outward = glm::normalize(line.points[last] - line.points[last - 1] -
                                              end * glm::dot(line.points[last] - line.points[last - 1], end));
    const glm::dvec3 side = glm::cross(end, outward);
    const size_t middle = last / 2;
    const glm::dvec3 across = glm::normalize(glm::cross(line.points[middle], line.points[middle + 1] - line.points[middle]));
    render::ReferenceSettings steps;
    steps.shaderSteps = true;
    const render::ReferenceModel reference(s, s.startTimeS, {});
    const render::ReferenceModel march(s, s.startTimeS, {}, steps);
    for (const render::ReferenceModel* model : {&reference, &march}) {
        auto downFrom = [&](glm::dvec3 footprint) {
            return glm::length(model->radiance((R + 400.0) * footprint, -footprint));
        };
        for (double rho : {0.5 * sigmaKm, sigmaKm, 2.0 * sigmaKm}) {
            const double inside = downFrom(moved(line.points[middle], across, rho));
            ASSERT_GT(inside, 0.0);
            for (double angleDeg : {-45.0, 0.0, 45.0}) {
                const double a = glm::radians(angleDeg);
                const double beyond = downFrom(moved(end, std::cos(a) * outward + std::sin(a) * side, rho));
                const double floatKm = model == &march ? 32.0 * std::ldexp(1.0, -24) * R : 0.0;
                EXPECT_NEAR(beyond / inside, 1.0, 1e-4 + rho * floatKm / (sigmaKm * sigmaKm))
                    << (model == &reference ? "reference" : "march") << ", rho " << rho << " km, " << angleDeg << " deg";
            }
        }
    }
}

// common/glsl.h reads a texture as GL does: texelFetch the texel; textureLod at level 0 of a linear,
// clamp-to-edge array bilinear between texel centres (i + 1/2)/n, clamped at the edges, in the layer round(r).
TEST(GlslSamplers, ReadAsGlSpecifies)
{
    namespace g = aurorawall::scene::f64;
    g::sampler2DArray s{2, 2, 2, {}};
    for (int layer = 0; layer < 2; ++layer)
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 2; ++x)
                for (int channel = 0; channel < 4; ++channel)
                    s.texels.push_back(float(100 * layer + 10 * y + x + channel));
    EXPECT_EQ(g::texelFetch(s, glm::ivec2(1, 1), 0), glm::dvec4(11.0, 12.0, 13.0, 14.0));
    EXPECT_EQ(g::textureLod(s, glm::dvec3(0.25, 0.25, 0.0), 0.0).x, 0.0);       // texel (0, 0)'s centre
    EXPECT_EQ(g::textureLod(s, glm::dvec3(0.5, 0.25, 0.0), 0.0).x, 0.5);        // halfway to (1, 0)
    EXPECT_EQ(g::textureLod(s, glm::dvec3(0.375, 0.625, 0.0), 0.0).x, 7.75);    // 1/4 along x, 3/4 along y
    EXPECT_EQ(g::textureLod(s, glm::dvec3(0.0, 1.0, 0.0), 0.0).x, 10.0);        // clamped to the edge texels
    EXPECT_EQ(g::textureLod(s, glm::dvec3(0.25, 0.25, 0.6), 0.0).x, 100.0);     // layer round(0.6) = 1
    EXPECT_EQ(g::textureLod(s, glm::dvec3(0.25, 0.25, 7.0), 0.0).w, 103.0);     // layers clamped
}
