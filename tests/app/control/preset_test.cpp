// The camera presets of `preset NAME` (control/remote_control.h): a preset's camera is its scene
// file's, by name under the preset folder or by path, and every refusal is one line naming the preset.
#include "app/control/command.h"
#include "app/control/geographic_camera.h"
#include "app/control/remote_control.h"
#include "cluster/master_clock.h"

#include <gtest/gtest.h>

#include <fstream>

namespace aurorawall::app::control {
namespace {

TEST(Preset, NameOrPathGivesTheScenesCamera)
{
    // ground-65n.toml: 65 N 20 E, 0.3 km up, looking north 30 degrees above the horizon.
    const scene::Camera byName = presetCamera("ground-65n", AW_SCENES_DIR);
    const GeographicPose p = poseOf(byName, 6371.0);
    EXPECT_NEAR(p.latitudeDeg, 65.0, 1e-9);
    EXPECT_NEAR(p.longitudeDeg, 20.0, 1e-9);
    EXPECT_NEAR(p.altitudeKm, 0.3, 1e-9);
    EXPECT_NEAR(p.pitchDeg, 30.0, 1e-9);
    const scene::Camera byPath = presetCamera(std::string(AW_SCENES_DIR) + "/ground-65n.toml", "/nonexistent");
    EXPECT_EQ(byPath.positionKm, byName.positionKm);
    EXPECT_EQ(byPath.forward, byName.forward);
    // benchmark-view flies along its view at 25.484 km/s; the preset keeps its speed.
    EXPECT_EQ(presetCamera("benchmark-view", AW_SCENES_DIR).speedKmPerS, 25.484);
}

TEST(Preset, AKeyedPathIsFollowedAtTheWallsTime)
{
    // benchmark-path.toml: from the benchmark view at 180 s straight along its direction at
    // 25.484 km/s until 210 s. The wall at 200 s shows the camera 20 s along that line, and follows it.
    cluster::ClockSettings settings;
    settings.frames = 0;
    settings.startTimeS = 200.0;
    settings.timeStepS = 0.5;
    cluster::MasterClock clock(settings, scene::Camera{}, 1.0);
    clock.next(false);
    const scene::Camera preset = presetCamera("benchmark-path", AW_SCENES_DIR);
    ASSERT_FALSE(preset.path.empty());
    clock.setCamera(preset);
    const glm::dvec3 start = glm::dvec3(-0.467287, -0.223999, 0.868115) * 6371.0;
    const glm::dvec3 direction = glm::normalize(glm::dvec3(-0.083353, 0.912453, 0.400601));
    // 1e-6 km: the path's interpolation of ~6500 km positions, and the second key's 17 digits.
    EXPECT_NEAR(glm::length(clock.camera().positionKm - (start + direction * (20.0 * 25.484))), 0.0, 1e-6);
    clock.next(false);
    EXPECT_NEAR(glm::length(clock.camera().positionKm - (start + direction * (20.5 * 25.484))), 0.0, 1e-6);
}

TEST(Preset, RefusalsNameThePresetOnOneLine)
{
    const std::string notAScene = testing::TempDir() + "/not-a-scene.toml";
    std::ofstream(notAScene) << "[wall]\nwidth = 3\n";
    const std::pair<std::string, const char*> cases[] = {
        {"nowhere", "preset nowhere: no such preset in"},
        {"nowhere", "ground-65n"}, // the list of presets
        {"../x", "preset ../x: a preset is a name"},
        {"/nonexistent/x.toml", "preset /nonexistent/x.toml: /nonexistent/x.toml is not a readable file"},
        {notAScene, "not-a-scene.toml"},
    };
    for (const auto& [name, reason] : cases) {
        try {
            presetCamera(name, AW_SCENES_DIR);
            ADD_FAILURE() << "'" << name << "' was accepted";
        } catch (const CommandError& e) {
            const std::string what = e.what();
            EXPECT_EQ(what.rfind("preset " + name + ": ", 0), 0u) << what;
            EXPECT_NE(what.find(reason), std::string::npos) << what << " (expected: " << reason << ")";
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        }
    }
}

} // namespace
} // namespace aurorawall::app::control
