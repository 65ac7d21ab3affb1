// The plasma scene component: its electron-strip frames (normalised, deterministic, cached, finite
// over a long run) and its settings' errors.
#include "common/input_error.h"
#include "components/fluid_detail/curtain_detail.h"
#include "components/plasma/plasma.h"
#include "components/plasma/sheet_frames.h"
#include "components/plasma/simulation/electron_sheet.h"
#include "components/registry.h"

#include "plasma_scene_text.h"
#include "scene/load_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

using namespace aurorawall;
using namespace aurorawall::components::plasma::simulation;

namespace {

// The scene's strip (config/scenes/plasma-curls.toml: n_b, B, Δt, 0.25 km cells, a 2 km sheet,
// mode 8 over 128 km, i.e. ka = 0.39) on a quarter of its length and half its width.
// The scene's cells and sheet on a strip of `cellsAlong` x `cellsAlong`/2 cells.
components::plasma::SheetFramesSpec smallSceneStrip(int cellsAlong = 128)
{
    components::plasma::Settings p;
    p.cellsAlong = cellsAlong;
    p.cellsAcross = cellsAlong / 2;
    p.stripLengthKm = 32.0 * cellsAlong / 128;
    p.stripWidthKm = 16.0 * cellsAlong / 128;
    p.seedMode = 2;
    p.frames = 4;
    p.timeBetweenFramesS = 10 * p.timeStepS;
    return components::plasma::sheetFramesSpec(p);
}

// The message of the input error loading `text` as a scene file throws ("" if none).
std::string sceneError(const std::string& text)
{
    return test::loadErrorOfText("plasma_settings.toml", text);
}

const std::string kSceneHead = test::plasmaSceneHead();

} // namespace

// Frame 0 is the strip: ∫F du = 1 km⁻¹·km in every column (the uniform strip's CIC deposit sums
// exactly), its peak 1/(2a) = 0.5 km⁻¹, its standard deviation across a/√3 widened by the CIC
// smoothing (variance + Δ²/6, Δ = 0.25 km). The frames are the same bits twice and through the cache.
TEST(PlasmaComponent, FramesAreTheStripNormalisedAndDeterministic)
{
    const components::plasma::SheetFramesSpec spec = smallSceneStrip();
    const components::roles::FluxFrames f = components::plasma::simulateSheetFrames(spec);
    ASSERT_EQ(f.flux.size(), std::size_t(128) * 64 * 4);
    for (int ix = 0; ix < f.nx; ++ix) {
        double column = 0.0;
        for (int iy = 0; iy < f.ny; ++iy)
            column += f.at(0, ix, iy) * f.texelKmY;
        EXPECT_NEAR(column, 1.0, 1e-5) << ix;
    }
    const components::fluid_detail::DetailShape shape = components::plasma::sheetDetailShape(spec, f);
    EXPECT_NEAR(1.0 / shape.peakScale, 0.5, 1e-5);
    EXPECT_NEAR(shape.fluxWidthKm, std::sqrt(1.0 / 3.0 + 0.25 * 0.25 / 6.0), 1e-3);
    EXPECT_DOUBLE_EQ(shape.stripLengthKm, 32.0);

    const components::roles::FluxFrames again = components::plasma::simulateSheetFrames(spec);
    EXPECT_EQ(std::memcmp(f.flux.data(), again.flux.data(), f.flux.size() * sizeof(float)), 0);
    const std::string dir = testing::TempDir() + "plasma_cache";
    std::filesystem::remove_all(dir);
    const components::plasma::CachedSheetFrames written = components::plasma::cachedSheetFrames(spec, dir);
    const components::plasma::CachedSheetFrames read = components::plasma::cachedSheetFrames(spec, dir);
    EXPECT_EQ(written.outcome.rfind("built", 0), 0u) << written.outcome;
    EXPECT_EQ(read.outcome, "read from cache");
    ASSERT_EQ(read.frames.flux.size(), f.flux.size());
    EXPECT_EQ(std::memcmp(f.flux.data(), read.frames.flux.data(), f.flux.size() * sizeof(float)), 0);
}

// The scene's cells and sheet (ω_pΔt = 0.446, ω_cΔt = 4.40) on a 64 x 32 strip over 10⁴ steps, far
// past the roll-up (about 900 steps): every electron stays finite and in the box, the potential
// finite (2.3 s).
TEST(PlasmaComponent, SceneStripStaysFiniteOverTenThousandSteps)
{
    const components::plasma::SheetFramesSpec spec = smallSceneStrip(64);
    ElectrostaticPic sim = sheetSimulation(spec.sheet);
    for (int n = 0; n < 10000; ++n)
        sim.step();
    const glm::dvec3 box = sim.grid().boxLength();
    for (const glm::dvec3& x : sim.electrons().position)
        ASSERT_TRUE(x.x >= 0.0 && x.x < box.x && x.y >= 0.0 && x.y < box.y) << x.x << ", " << x.y;
    for (const glm::dvec3& v : sim.electrons().velocity)
        ASSERT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
    for (double phi : sim.potential())
        ASSERT_TRUE(std::isfinite(phi));
}

TEST(PlasmaComponent, SettingsErrorsNameFileLineAndKey)
{
    EXPECT_EQ(sceneError(kSceneHead + "[plasma]\nframes = 4\n"), "");
    // ω_p = 1.784e5 rad/s at 1e7 m⁻³: Δt = 1.2e-5 s gives ω_pΔt = 2.14.
    const std::string unstable = sceneError(kSceneHead + "[plasma]\ntime_step_s = 1.2e-5\n");
    EXPECT_NE(unstable.find("plasma_settings.toml:13"), std::string::npos) << unstable;
    EXPECT_NE(unstable.find("plasma.time_step_s"), std::string::npos) << unstable;
    EXPECT_NE(unstable.find("unstable"), std::string::npos) << unstable;
    EXPECT_NE(sceneError(kSceneHead + "[plasma]\nsheet_thickness_km = 20.0\n").find("plasma.sheet_thickness_km"),
              std::string::npos);
    EXPECT_NE(sceneError(kSceneHead + "[plasma]\nsheet_thickness_km = 0.3\n").find("at least 2 cells"),
              std::string::npos);
    EXPECT_NE(sceneError(kSceneHead + "[plasma]\nmagnetic_field_t = 0.0\n").find("plasma.magnetic_field_t"),
              std::string::npos);
    EXPECT_NE(sceneError(kSceneHead + "[plasma]\ntime_between_frames_s = 1.0\n").find("plasma.time_between_frames_s"),
              std::string::npos);
    EXPECT_NE(sceneError(kSceneHead + "[plasma]\nseed_mode = 200\n").find("plasma.seed_mode"), std::string::npos);
    EXPECT_NE(sceneError(kSceneHead + "[plasma]\nelectron_density = 1e7\n").find("electron_density"),
              std::string::npos);
    std::string both = kSceneHead;
    both.replace(both.find("\"plasma\""), 8, "\"plasma\", \"fluid_detail\"");
    EXPECT_NE(sceneError(both).find("both plasma and fluid_detail"), std::string::npos) << sceneError(both);
    // Two providers of one role: an error of the components key, naming the file and the role.
    EXPECT_NE(sceneError(both).find("plasma_settings.toml:"), std::string::npos) << sceneError(both);
    EXPECT_NE(sceneError(both).find("scene.components: "), std::string::npos) << sceneError(both);
    EXPECT_NE(sceneError(both).find("curtain detail"), std::string::npos) << sceneError(both);
    std::string alone = kSceneHead;
    alone.replace(alone.find("\"aurora\", "), 10, "");
    alone.erase(alone.find("[[aurora.curtain]]"));
    EXPECT_NE(sceneError(alone).find("'plasma' needs 'curtains' (provided by aurora)"), std::string::npos) << sceneError(alone);
}

// device: "cpu" (the default) or "gpu"; anything else names the file, line and key.
TEST(PlasmaComponent, DeviceIsCpuOrGpu)
{
    EXPECT_EQ(sceneError(kSceneHead + "[plasma]\ndevice = \"gpu\"\n"), "");
    const std::string bad = sceneError(kSceneHead + "[plasma]\ndevice = \"fpga\"\n");
    EXPECT_NE(bad.find("plasma_settings.toml:13: plasma.device"), std::string::npos) << bad;
    EXPECT_EQ(components::plasma::Settings().device, components::plasma::Settings::Device::Cpu);
}

// The step a time shows: the curls' detail phase times the frames' steps (frame k at phase
// k/(frames − 1) is step k·stepsPerFrame, as the CPU frames); the box's clock looping over box_play_s.
TEST(PlasmaComponent, ClockToStepIsTheFramesMapping)
{
    namespace plasma = components::plasma;
    const plasma::SheetFramesSpec spec = smallSceneStrip(); // 4 frames of 10 steps
    EXPECT_EQ(plasma::curlsStep(spec, 0.0), 0);
    EXPECT_EQ(plasma::curlsStep(spec, 1.0 / 3.0), 10);
    EXPECT_EQ(plasma::curlsStep(spec, 0.5), 15);
    EXPECT_EQ(plasma::curlsStep(spec, 1.0), 30);
    plasma::Settings box;
    box.kind = plasma::Settings::Kind::Box;
    box.boxFrames = 24;
    box.boxTimeBetweenFramesS = 5 * box.boxTimeStepS; // 5 steps a frame
    box.boxPlayS = 12.0;
    EXPECT_DOUBLE_EQ(plasma::boxFramePosition(box, 6.0), 11.5);
    EXPECT_EQ(plasma::boxStep(box, 6.0), 58); // 57.5 rounded away from zero
    EXPECT_EQ(plasma::boxStep(box, 0.0), 0);
    EXPECT_EQ(plasma::boxStep(box, 12.0), 0);  // the loop starts again
    EXPECT_EQ(plasma::boxStep(box, 18.0), 58);
    EXPECT_EQ(plasma::boxStep(box, 11.999999), 115);
}
