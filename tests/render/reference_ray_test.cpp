// The double-precision CPU reference of the model (src/render/reference_ray.h) against the GPU
// render at its finest settings, and the reference's own convergence, on the substorm scene
// (without stars and planet_texture, which the reference does not model).
#include "components/aurora/tools/aurora_accuracy.h"
#include "components/fluid_detail/simulation/curtain_detail.h"
#include "gl/context.h"
#include "components/fluid_detail/curtain_detail.h"
#include "components/aurora/aurora.h"
#include "components/registry.h"
#include "components/roles/curtain_detail.h"
#include "aurora_float_bound.h"
#include "render/reference_ray.h"
#include "scene_samples.h"
#include "scene/scene.h"
#include "wall/tile_rays.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

using namespace aurorawall;
using aurorawall::components::roles::curtainDetailData;
using aurorawall::test::litPixels;
using aurorawall::test::placeCamera;

namespace {

const std::string kSource = AURORAWALL_SOURCE_DIR;

// The substorm scene at the renderer's finest settings: 0.25 km steps (with skipping), the largest
// tables and footprint map, 1 km polylines.
scene::Scene finestSubstorm()
{
    scene::Scene s = scene::withoutUnmodelled(components::loadScene(kSource + "/config/scenes/substorm.toml"));
    components::aurora::tools::applyFinestSettings(s);
    return s;
}

class ReferenceRay : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        context_ = gl::createContext(gl::Backend::Egl);
        scene_ = new scene::Scene(finestSubstorm());
        view_ = new accuracy::SceneView(accuracy::sceneView(*scene_, kSource + "/config/walls/single.toml", {64, 36}));
        frames_ = new components::roles::FluxFrames(components::fluid_detail::simulation::simulateCurtainDetail(components::fluid_detail::curtainDetailSpec(scene_->settings<components::fluid_detail::Settings>())));
    }
    static void TearDownTestSuite()
    {
        delete frames_;
        delete view_;
        delete scene_;
        context_.reset();
    }
    // One 8-bit step of the linear preview at the scene's exposure: below it a difference is invisible.
    static double floor() { return 1.0 / (255.0 * scene_->exposure); }

    // The GPU render of `s` at `view` against the CPU reference at 16 of its lit pixels: those of the
    // first render compared (`pixels` and `reference` empty), so that variants share them.
    static accuracy::RelativeError againstReference(const scene::Scene& s, const accuracy::SceneView& view,
                                                    const render::ReferenceModel& model, std::vector<glm::ivec2>& pixels,
                                                    std::vector<glm::dvec3>& reference)
    {
        const io::Image gpu = accuracy::renderView(s, view, kSource + "/shaders", 0).image;
        if (pixels.empty()) {
            pixels = litPixels(gpu, floor(), 16);
            reference = accuracy::referencePixels(model, view, pixels, 2);
        }
        std::vector<glm::dvec3> values;
        for (const glm::ivec2& p : pixels)
            values.push_back(accuracy::pixelRadiance(gpu, p.x, p.y));
        const accuracy::RelativeError e = accuracy::relativeError(values, reference, floor());
        EXPECT_EQ(e.pixels, pixels.size());
        return e;
    }

    static std::unique_ptr<gl::Context> context_;
    static scene::Scene* scene_;
    static accuracy::SceneView* view_;
    static components::roles::FluxFrames* frames_;
};

std::unique_ptr<gl::Context> ReferenceRay::context_;
scene::Scene* ReferenceRay::scene_ = nullptr;
accuracy::SceneView* ReferenceRay::view_ = nullptr;
components::roles::FluxFrames* ReferenceRay::frames_ = nullptr;

} // namespace

// The GPU against the same march in double (ReferenceSettings::shaderSteps) at 16 lit pixels of the march's
// image (most lit by the sky's glow): only float is left between them, bounded per pixel by AuroraFloatBound
// (aurora_float_bound.h) from this scene's data. Then against the fine CPU reference, whose difference from
// the march in double is its discretization (tests/render/shader_steps_test.cpp holds it to 1e-3): the two
// bounds add. Both sub-step fluxes: the middle column's bound is the tighter (the exact pieces' moments
// add up to 608 u Q / cell of the crossing). Measured (llvmpipe), the middle column against the march RMS
// 3.3e-5, max 1.1e-4, at most 18% of a pixel's bound (the bounds reach 5.8e-2 of a pixel, from the flux's
// slopes); the exact pieces RMS 2.7e-5, max 7.6e-5; against the reference RMS 3.6e-5 and 4.9e-5, max 1.2e-4
// and 1.9e-4 (before the curtain-normal fix of aurora_curtains.glsl it was RMS 1.7e-2: the test caught the
// float bug).
TEST_F(ReferenceRay, GpuAtItsFinestSettingsAgreesWithTheReference)
{
    for (bool exact : {false, true}) {
        scene::Scene s = *scene_;
        s.settings<components::aurora::Settings>().exactSubSteps = exact;
        const io::Image gpu = accuracy::renderView(s, *view_, kSource + "/shaders", 0).image;
        render::ReferenceSettings shaderSteps;
        shaderSteps.shaderSteps = true;
        const render::ReferenceModel march(s, view_->frame.timeS, curtainDetailData(frames_), shaderSteps);
        const std::vector<glm::dvec3> marchImage = test::referenceImage(march, *view_, gpu.width, gpu.height);
        const std::vector<glm::ivec2> pixels = test::litPixels(marchImage, gpu.width, floor(), 16);
        const render::ReferenceModel model(s, view_->frame.timeS, curtainDetailData(frames_));
        const std::vector<glm::dvec3> reference = accuracy::referencePixels(model, *view_, pixels, 2);
        std::vector<glm::dvec3> values, marched;
        for (const glm::ivec2& p : pixels) {
            values.push_back(accuracy::pixelRadiance(gpu, p.x, p.y));
            marched.push_back(marchImage[size_t(p.y * gpu.width + p.x)]);
        }
        // The reference lies within its discretization (1e-3 relative) of the march in double.
        const test::FloatBoundCheck check =
            test::expectWithinFloatBound(s, *frames_, march, *view_, pixels, values, marched, reference, 1e-3);
        const accuracy::RelativeError f = accuracy::relativeError(values, marched, floor());
        const accuracy::RelativeError e = accuracy::relativeError(values, reference, floor());
        std::printf("%s: float bound: dh %.3g km, dq %.3g km; at most %.3g of a pixel\n", exact ? "exact" : "midpoint",
                    check.dh, check.dq, check.largestBound);
        std::printf("GPU (0.25 km, finest tables) vs the march in double at %zu pixels: rms %.3g, max %.3g, at most "
                    "%.3g of the float bound; vs CPU reference: rms %.3g, max %.3g\n",
                    f.pixels, f.rms, f.max, check.largestShare, e.rms, e.max);
        EXPECT_EQ(f.pixels, pixels.size());
        EXPECT_EQ(e.pixels, pixels.size());
    }
}

// Looking straight up from the ground under the break-up's equatorward arc (65.2° N, 21.0° E, t = 180 s):
// the rays run along the sheet and barely move across its detail. The exact pieces' closed form is a
// difference of running integrals held in float texels; where the ray's share of a piece is far
// smaller than those integrals, rounding left up to 20% of a pixel here (0.25 km runs) until such
// pieces took the end-point rule (aurora_curtains.glsl, curtainEnergyExact). The GPU against the march in double over the 8x8 pixels around the
// zenith, within the float bound as above; that bound admits the closed form's whole rounding, so the
// GPU is also held to the renderer's accuracy goal, 1% RMS of the CPU reference over them (ACCURACY.md;
// with the closed form everywhere it was 5.3%, max 41%).
TEST_F(ReferenceRay, GpuLookingUpAlongACurtainIsWithinTheFloatBound)
{
    scene::Scene s = *scene_;
    s.settings<components::aurora::Settings>().exactSubSteps = true;
    s.camera.positionKm = scene::planetPoint(65.2, 21.0, s.planetRadiusKm);
    s.camera.forward = glm::normalize(s.camera.positionKm);
    const glm::dvec3 north(0.0, 0.0, 1.0);
    s.camera.up = glm::normalize(north - s.camera.forward * glm::dot(north, s.camera.forward));
    const accuracy::SceneView view = accuracy::sceneView(s, kSource + "/config/walls/single.toml", {64, 36});
    const io::Image gpu = accuracy::renderView(s, view, kSource + "/shaders", 0).image;
    render::ReferenceSettings shaderSteps;
    shaderSteps.shaderSteps = true;
    const render::ReferenceModel march(s, view.frame.timeS, curtainDetailData(frames_), shaderSteps);
    std::vector<glm::ivec2> pixels;
    for (int y = 14; y < 22; ++y)
        for (int x = 28; x < 36; ++x)
            pixels.emplace_back(x, y);
    const std::vector<glm::dvec3> marched = accuracy::referencePixels(march, view, pixels, 2);
    const render::ReferenceModel model(s, view.frame.timeS, curtainDetailData(frames_));
    const std::vector<glm::dvec3> reference = accuracy::referencePixels(model, view, pixels, 2);
    std::vector<glm::dvec3> values;
    for (const glm::ivec2& p : pixels) {
        values.push_back(accuracy::pixelRadiance(gpu, p.x, p.y));
        ASSERT_GE(glm::length(marched[values.size() - 1]), floor()) << "pixel " << p.x << ", " << p.y; // lit
    }
    const test::FloatBoundCheck check =
        test::expectWithinFloatBound(s, *frames_, march, view, pixels, values, marched, reference, 1e-3);
    const accuracy::RelativeError e = accuracy::relativeError(values, marched, floor());
    const accuracy::RelativeError r = accuracy::relativeError(values, reference, floor());
    std::printf("looking up along a curtain: GPU vs the march in double at %zu pixels: rms %.3g, max %.3g, at most "
                "%.3g of the float bound; vs the CPU reference: rms %.3g, max %.3g\n",
                e.pixels, e.rms, e.max, check.largestShare, r.rms, r.max);
    EXPECT_EQ(r.pixels, pixels.size());
    EXPECT_LT(r.rms, 1e-2);
}

// From 1e8 km, zoomed until a pixel spans 1.5e-7 rad (15 km at the aurora): the GPU holds positions in
// float, 8 km steps at the camera's distance, so rays that started there met the curtains with
// jumbled positions and the picture broke into blocks. Rays start beyond the scene instead
// (cluster::rayStart), from double and a stable offset across the view (render/tile_rays.glsl). The GPU
// against the CPU reference at 16 lit pixels, held to the renderer's 1% RMS goal (ACCURACY.md).
// Measured (llvmpipe): RMS 8.0e-4, max 1.9e-3; with rays that start at the camera in float, RMS 0.24,
// max 0.95.
TEST_F(ReferenceRay, GpuSeesANarrowViewFromFarInSpaceAsTheReferenceDoes)
{
    accuracy::SceneView view = accuracy::sceneView(*scene_, kSource + "/config/walls/single.toml", {64, 36});
    const glm::dvec3 lookAt(-2769.7433293745, -193.6793209249631, 5900.377209130914); // 150 km up, 65 N
    const glm::dvec3 forward = glm::normalize(glm::dvec3(-0.0698, 0.99756, 0.0));
    const glm::dvec3 north(0.0, 0.0, 1.0);
    cluster::FrameState& f = view.frame;
    placeCamera(f, lookAt - 1e8 * forward, forward, glm::normalize(north - forward * glm::dot(north, forward)));
    const double pixelRad = 1.5e-7;
    f.zoom = wall::tanHalfVerticalFieldOfView(view.wall) / std::tan(0.5 * 36 * pixelRad);
    const render::ReferenceModel model(*scene_, f.timeS, curtainDetailData(frames_));
    std::vector<glm::ivec2> pixels;
    std::vector<glm::dvec3> reference;
    const accuracy::RelativeError e = againstReference(*scene_, view, model, pixels, reference);
    ASSERT_EQ(pixels.size(), 16u) << "the view shows the aurora";
    std::printf("1e8 km away, 1.5e-7 rad a pixel: GPU vs the CPU reference at %zu pixels: rms %.3g, max %.3g\n",
                e.pixels, e.rms, e.max);
    EXPECT_LT(e.rms, 1e-2);
}

// Halving the reference's step (0.05 -> 0.025 km) changes it by less than 1e-3 relative, at the
// brightest aurora pixels (where the emission integral dominates).
TEST_F(ReferenceRay, ReferenceConverges)
{
    const io::Image gpu = accuracy::renderView(*scene_, *view_, kSource + "/shaders", 0).image;
    const std::vector<glm::ivec2> all = test::brightestFirst(gpu, test::allPixels(gpu));
    // Four of the brightest twenty, spread out.
    const std::vector<glm::ivec2> pixels = {all[0], all[6], all[12], all[19]};
    render::ReferenceSettings fine, finer;
    fine.stepKm = 0.05;
    finer.stepKm = 0.025;
    const scene::RoleData detail = curtainDetailData(frames_);
    const std::vector<glm::dvec3> a =
        accuracy::referencePixels(render::ReferenceModel(*scene_, view_->frame.timeS, detail, fine), *view_, pixels, 2);
    const std::vector<glm::dvec3> b =
        accuracy::referencePixels(render::ReferenceModel(*scene_, view_->frame.timeS, detail, finer), *view_, pixels, 2);
    const accuracy::RelativeError e = accuracy::relativeError(a, b, 0.0);
    std::printf("reference 0.05 km vs 0.025 km at the brightest pixels: max %.3g\n", e.max);
    EXPECT_LT(e.max, 1e-3);
}

TEST_F(ReferenceRay, RejectsWhatItDoesNotModel)
{
    const scene::Scene full = components::loadScene(kSource + "/config/scenes/substorm.toml");
    EXPECT_THROW(render::ReferenceModel(full, 0.0, curtainDetailData(frames_)), std::invalid_argument);
    EXPECT_THROW(render::ReferenceModel(*scene_, 0.0, {}), std::invalid_argument);
}

// The default march (12 km steps, each cut into sub-steps of at most 1 km in altitude and 0.75 of the
// detail's 0.25 km cells in the coordinate not integrated over, the flux integrated exactly along the
// slanted path) and the same steps with 0.25 km sub-steps in altitude, against the CPU reference at views
// along the paper's benchmark path: at the start (70 km up), inside the aurora layer (frame 28, 144 km
// up) and above it (frame 60, 251 km up). Point samples every 2 km were 4-8% RMS off at these views.
// Measured here: RMS 0.011%, 0.034%, 0.20% with the defaults and 0.015%, 0.033%, 0.20% with 0.25 km
// sub-steps (finer sub-steps do not move frame 60: what is left there is not theirs). Held to the 1% RMS
// the defaults are chosen for (docs/ACCURACY.md).
TEST_F(ReferenceRay, CoarseStepsIntegratedAcrossTheCurtainStayNearTheReference)
{
    for (long long frame : {0LL, 28LL, 60LL}) {
        scene::Scene s = scene::withoutUnmodelled(components::loadScene(kSource + "/config/scenes/benchmark-view.toml"));
        const accuracy::SceneView view = accuracy::sceneView(s, kSource + "/config/walls/single.toml", {64, 36}, frame);
        const render::ReferenceModel model(s, view.frame.timeS, curtainDetailData(frames_));
        std::vector<glm::ivec2> pixels;
        std::vector<glm::dvec3> reference;
        auto& aurora = s.settings<components::aurora::Settings>();
        for (double resolveKm : {aurora.resolveKm, 0.25}) {
            aurora.resolveKm = resolveKm;
            const accuracy::RelativeError e = againstReference(s, view, model, pixels, reference);
            std::printf("frame %lld, %g km steps, %.2f km sub-steps vs CPU reference at %zu pixels: rms %.3g, max %.3g\n",
                        frame, aurora.stepKm, resolveKm, e.pixels, e.rms, e.max);
            EXPECT_LT(e.rms, 1e-2) << "frame " << frame;
        }
    }
}

// Where a sheet of the detail is tilted in (s, u), the column read at a sub-step's middle
// (sub_step_flux = "midpoint") misses where the ray crosses it, an error first order in the sub-step's
// change along: at frame 28 of the benchmark path one pixel of a 64x36 view is 9.2% too bright. The
// exact integral along the slanted path (sub_step_flux = "exact", the default) leaves there the
// emission's position within a run of pieces, the reference's own 0.05 km midpoint rule, and where the
// curtain is followed: the march carries the step's coordinates along the curtain's smooth curvature, the
// reference takes the nearest of its 2 km segments, whose coordinates jump by |u| θ where that changes.
// Measured: the middle column's largest error at 16 lit pixels 9.1%, the exact integral's 0.096% (0.055%
// with coordinates linear over the step, though over the whole view those were 0.23% RMS off the finest
// render and the curvature's are 0.10%: docs/aurora-physics.md); held to more than 5% (the view still
// shows the tilted sheet) and to less than 0.2%, a forty-fifth of the middle column's.
TEST_F(ReferenceRay, ExactSubStepsRemoveTheMiddleColumnsErrorAtATiltedSheet)
{
    scene::Scene s = scene::withoutUnmodelled(components::loadScene(kSource + "/config/scenes/benchmark-view.toml"));
    const accuracy::SceneView view = accuracy::sceneView(s, kSource + "/config/walls/single.toml", {64, 36}, 28);
    const render::ReferenceModel model(s, view.frame.timeS, curtainDetailData(frames_));
    std::vector<glm::ivec2> pixels;
    std::vector<glm::dvec3> reference;
    double largest[2] = {0.0, 0.0};
    for (bool exact : {false, true}) {
        s.settings<components::aurora::Settings>().exactSubSteps = exact;
        const accuracy::RelativeError e = againstReference(s, view, model, pixels, reference);
        std::printf("frame 28, sub_step_flux = %s vs CPU reference at %zu pixels: rms %.3g, max %.3g\n",
                    exact ? "exact" : "midpoint", e.pixels, e.rms, e.max);
        largest[exact] = e.max;
    }
    EXPECT_GT(largest[0], 0.05);
    EXPECT_LT(largest[1], 2e-3);
}

// The smooth curtain (no fluid detail: the Gaussian profile integrated across in closed form, erfc
// of non-negative arguments) at 8 km steps against the CPU reference, on the quiet arc seen from
// the ground. Measured: RMS 1.3e-4, max 4.9e-4. Held to RMS 1e-3.
TEST_F(ReferenceRay, SmoothCurtainsIntegratedAcrossStayNearTheReference)
{
    scene::Scene s = scene::withoutUnmodelled(components::loadScene(kSource + "/config/scenes/quiet-arc.toml"));
    ASSERT_FALSE(s.has("fluid_detail"));
    s.settings<components::aurora::Settings>().stepKm = 8.0;
    s.settings<components::aurora::Settings>().resolveKm = 0.5;
    const accuracy::SceneView view = accuracy::sceneView(s, kSource + "/config/walls/single.toml", {64, 36});
    const io::Image gpu = accuracy::renderView(s, view, kSource + "/shaders", 0).image;
    const double floor = 1.0 / (255.0 * s.exposure);
    const std::vector<glm::ivec2> pixels = litPixels(gpu, floor, 16);
    const render::ReferenceModel model(s, view.frame.timeS, {});
    const std::vector<glm::dvec3> reference = accuracy::referencePixels(model, view, pixels, 2);
    std::vector<glm::dvec3> values;
    for (const glm::ivec2& p : pixels)
        values.push_back(accuracy::pixelRadiance(gpu, p.x, p.y));
    const accuracy::RelativeError e = accuracy::relativeError(values, reference, floor);
    std::printf("quiet arc, 8 km steps, 0.5 km sub-steps vs CPU reference at %zu pixels: rms %.3g, max %.3g\n",
                e.pixels, e.rms, e.max);
    EXPECT_EQ(e.pixels, pixels.size());
    EXPECT_LT(e.rms, 1e-3);
}

// A view nobody chose (drawn at random above the quiet arc: 683 km up, t = 427.4 s) sees the arc's west
// end against the limb, where rays graze the disc of the curtain's reach around its end. Sub-steps once
// covered the rectangle around the curtain and kept or dropped each by its middle, so one straddling
// the disc's edge counted wholly or not at all: the tip's pixel was 12.6% off the CPU reference (the
// view 1.8% RMS). The sub-steps now cover the stadium exactly (withinStadium). The GPU's defaults
// against the reference at the lit pixels of the 9x9 around the tip, held to the 1% RMS goal
// (ACCURACY.md). Measured (llvmpipe): RMS 2.3e-4, max 1.1e-3 over 42 pixels; before, RMS 1.9e-2, max 0.125.
TEST_F(ReferenceRay, RaysGrazingACurtainsEndStayNearTheReference)
{
    scene::Scene s = scene::withoutUnmodelled(components::loadScene(kSource + "/config/scenes/quiet-arc.toml"));
    s.startTimeS = 427.386;
    accuracy::SceneView view = accuracy::sceneView(s, kSource + "/config/walls/single.toml", {160, 90});
    cluster::FrameState& f = view.frame;
    placeCamera(f, glm::dvec3(-2118.127541, -1715.742898, 6505.780996),
                glm::normalize(glm::dvec3(-0.461224, 0.623983, -0.630807)),
                glm::normalize(glm::dvec3(0.808966, 0.587768, -0.010078)));
    const io::Image gpu = accuracy::renderView(s, view, kSource + "/shaders", 0).image;
    const double floor = 1.0 / (255.0 * s.exposure);
    std::vector<glm::ivec2> pixels;
    for (int y = 12; y <= 20; ++y)
        for (int x = 48; x <= 56; ++x)
            if (glm::length(accuracy::pixelRadiance(gpu, x, y)) >= floor)
                pixels.emplace_back(x, y);
    ASSERT_GE(pixels.size(), 5u) << "the view shows the arc's end";
    const render::ReferenceModel model(s, f.timeS, {});
    const std::vector<glm::dvec3> reference = accuracy::referencePixels(model, view, pixels, 2);
    std::vector<glm::dvec3> values;
    for (const glm::ivec2& p : pixels)
        values.push_back(accuracy::pixelRadiance(gpu, p.x, p.y));
    const accuracy::RelativeError e = accuracy::relativeError(values, reference, floor);
    std::printf("quiet arc's end, grazing rays: GPU vs CPU reference at %zu pixels: rms %.3g, max %.3g\n", e.pixels,
                e.rms, e.max);
    EXPECT_EQ(e.pixels, pixels.size());
    EXPECT_LT(e.rms, 1e-2);
}

// A curtain emits within its own reach of its centre line and of its ends (4 sigma for the smooth
// profile), whatever other curtains the scene holds: a 2 km curtain's end, seen from above, is the same
// with or without a 10 km curtain 2000 km away, on the GPU and in the CPU reference. When the reach was
// the largest of the scene's, the thick curtain widened the thin one's rounded end from 4 km to 20 km.
TEST_F(ReferenceRay, EachCurtainEmitsWithinItsOwnReach)
{
    const std::string thin = R"(
[scene]
name = "curtain end"
components = ["planet", "atmosphere", "aurora"]
exposure = 600.0
[atmosphere]
top_km = 75.0
scale_height_km = 8.0
[aurora]
step_km = 2.0
[[aurora.curtain]]
thickness_km = 2.0
points_lat_lon_deg = [[66.0, 10.0], [66.0, 20.0]]
energy_flux_erg_cm2_s = 5.0
energy_kev = 3.0
[camera]
latitude_deg = 66.0
longitude_deg = 20.0
altitude_km = 600.0
heading_deg = 270.0
elevation_deg = -80.0
)";
    const std::string thick = R"(
[[aurora.curtain]]
thickness_km = 10.0
points_lat_lon_deg = [[60.0, -25.0], [60.0, -20.0]]
energy_flux_erg_cm2_s = 5.0
energy_kev = 3.0
)";
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "aurorawall-own-reach";
    std::filesystem::create_directories(dir);
    auto load = [&](const std::string& name, const std::string& text) {
        std::ofstream(dir / name) << text;
        return components::loadScene((dir / name).string());
    };
    const scene::Scene alone = load("alone.toml", thin);
    const scene::Scene withThick = load("with-thick.toml", thin + thick);
    std::filesystem::remove_all(dir);

    const accuracy::SceneView view = accuracy::sceneView(alone, kSource + "/config/walls/single.toml", {64, 36});
    const double floor = 1.0 / (255.0 * alone.exposure);
    const io::Image a = accuracy::renderView(alone, view, kSource + "/shaders", 0).image;
    const io::Image b = accuracy::renderView(withThick, view, kSource + "/shaders", 0).image;
    std::vector<glm::dvec3> valuesA, valuesB;
    for (int y = 0; y < 36; ++y)
        for (int x = 0; x < 64; ++x) {
            valuesA.push_back(accuracy::pixelRadiance(a, x, y));
            valuesB.push_back(accuracy::pixelRadiance(b, x, y));
        }
    const accuracy::RelativeError gpu = accuracy::relativeError(valuesB, valuesA, floor);
    const std::vector<glm::ivec2> pixels = litPixels(a, floor, 8);
    const accuracy::RelativeError cpu =
        accuracy::relativeError(accuracy::referencePixels(render::ReferenceModel(withThick, view.frame.timeS, {}), view, pixels, 2),
                           accuracy::referencePixels(render::ReferenceModel(alone, view.frame.timeS, {}), view, pixels, 2),
                           floor);
    std::printf("thin curtain's end with a thick one far away against alone: GPU %zu pixels, max %.3g; "
                "CPU reference %zu pixels, max %.3g\n",
                gpu.pixels, gpu.max, cpu.pixels, cpu.max);
    EXPECT_GT(gpu.pixels, 100u);
    EXPECT_LT(gpu.max, 1e-4);
    EXPECT_EQ(cpu.pixels, pixels.size());
    EXPECT_LT(cpu.max, 1e-9);
}

// Views nobody chose: four views of the benchmark scene drawn at random from seed 1 (one of each kind: on
// the ground, inside the auroral layer, above it and far in space, at random times;
// src/accuracy/random_views.h), each against the CPU reference at 16 of the pixels where the aurora
// gives at least half the radiance. The default's exact flux held to the 1% RMS target; the middle
// column to 4%, one pixel of 16 as far off as the worst `launch/accuracy-views` found for it (15.7%).
// Measured: RMS 0.034%, 0.14%, 0.30%, 0.15% (middle column), 0.018%, 0.10%, 0.10%, 0.069% (exact).
TEST_F(ReferenceRay, StaysNearTheReferenceAtViewsDrawnAtRandom)
{
    scene::Scene s = scene::withoutUnmodelled(components::loadScene(kSource + "/config/scenes/benchmark-view.toml"));
    const accuracy::SceneView start = accuracy::sceneView(s, kSource + "/config/walls/single.toml", {64, 36});
    accuracy::SceneAccuracySettings settings;
    settings.views = 4;
    settings.seed = 1;
    settings.pixels = 16;
    for (bool exact : {false, true}) {
        s.settings<components::aurora::Settings>().exactSubSteps = exact;
        std::vector<components::aurora::tools::ViewError> errors;
        components::aurora::tools::measureViews(s, start, kSource + "/shaders", settings,
                                                [&](const components::aurora::tools::ViewError& e) { errors.push_back(e); });
        ASSERT_EQ(errors.size(), 4u);
        for (const components::aurora::tools::ViewError& e : errors) {
            std::printf("%s, %s view, %.0f km up, t = %.0f s: %zu aurora pixels; against the CPU reference rms %.3g, "
                        "max %.3g\n", exact ? "exact" : "middle column", accuracy::viewKindName(e.kind),
                        glm::length(e.frame.cameraPositionKm) - s.planetRadiusKm, e.frame.timeS, e.auroraPixels,
                        e.cpu.rms, e.cpu.max);
            EXPECT_GE(e.auroraPixels, 16u) << accuracy::viewKindName(e.kind);
            EXPECT_EQ(e.cpu.pixels, 16u) << accuracy::viewKindName(e.kind);
            EXPECT_LT(e.cpu.rms, exact ? 0.01 : 0.04) << accuracy::viewKindName(e.kind);
        }
    }
}
