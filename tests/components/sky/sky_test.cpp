// The sky's settings as a scene file gives them: each light's direction from where it stands in a
// site's sky, checked against the site's own local frame built here from latitude and longitude, its
// default illuminance, and one-line errors for what the shader cannot take.
#include "common/planet_frame.h"
#include "physics/constants.h"
#include "components/registry.h"
#include "components/sky/sky.h"
#include "scene/load_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace aurorawall;
using test::loadErrorOfText;
using test::temporarySceneFile;

namespace {

const std::string kHead = "[scene]\nname = \"sky\"\ncomponents = [\"planet\", \"atmosphere\", \"sky\"]\n"
                          "[camera]\nlatitude_deg = 65.0\nlongitude_deg = 20.0\naltitude_km = 0.3\n"
                          "heading_deg = 0.0\nelevation_deg = 10.0\n";

std::string light(double elevationDeg, double azimuthDeg, const std::string& more = "")
{
    return "[[sky.light]]\nsite_latitude_deg = 65.0\nsite_longitude_deg = 20.0\nelevation_deg = " +
           std::to_string(elevationDeg) + "\nazimuth_deg = " + std::to_string(azimuthDeg) + "\n" + more;
}

components::sky::Settings skyOf(const std::string& name, const std::string& text)
{
    return components::loadScene(temporarySceneFile(name, text)).settings<components::sky::Settings>();
}

double degrees(double radians)
{
    return radians * 180.0 / physics::kPi;
}

} // namespace

// Elevation and azimuth read back from the direction in the site's frame: up the site's unit vector,
// north the way its latitude grows (a central difference of the unit vectors, exact to ~1e-10),
// east = north × up (right-handed, as on a map seen from above).
TEST(Sky, LightStandsWhereTheSiteSeesIt)
{
    const struct {
        double elevationDeg, azimuthDeg;
    } cases[] = {{-11.0, 250.0}, {30.0, 10.0}, {5.0, 90.0}, {60.0, 180.0}};
    const glm::dvec3 up = common::unitFromLatLon(65.0, 20.0);
    const glm::dvec3 north =
        glm::normalize(common::unitFromLatLon(65.0 + 1e-4, 20.0) - common::unitFromLatLon(65.0 - 1e-4, 20.0));
    const glm::dvec3 east = glm::cross(north, up);
    for (const auto& c : cases) {
        const auto s = skyOf("light.toml", kHead + light(c.elevationDeg, c.azimuthDeg));
        ASSERT_EQ(s.lights.size(), 1u);
        const glm::dvec3 d = s.lights[0].direction;
        EXPECT_NEAR(glm::length(d), 1.0, 1e-12);
        EXPECT_NEAR(degrees(std::asin(glm::dot(d, up))), c.elevationDeg, 1e-6);
        const double azimuth = degrees(std::atan2(glm::dot(d, east), glm::dot(d, north)));
        EXPECT_NEAR(std::remainder(azimuth - c.azimuthDeg, 360.0), 0.0, 1e-6) << c.azimuthDeg;
        // The Sun's illuminance above the atmosphere unless the file gives one.
        EXPECT_EQ(s.lights[0].illuminanceLux, glm::dvec3(1.28e5));
    }
    const auto moon = skyOf("moon.toml", kHead + light(20.0, 180.0, "illuminance_lux = 0.26\n"));
    EXPECT_EQ(moon.lights[0].illuminanceLux, glm::dvec3(0.26));
}

TEST(Sky, ShippedTwilightHasTheSunBelowTheHorizon)
{
    const auto s = components::loadScene(std::string(AURORAWALL_SOURCE_DIR) + "/config/scenes/twilight.toml")
                       .settings<components::sky::Settings>();
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_NEAR(degrees(std::asin(glm::dot(s.lights[0].direction, common::unitFromLatLon(65.0, 20.0)))), -11.0, 1e-6);
    EXPECT_FALSE(s.nestedMarch);
}

TEST(Sky, RefusesWhatTheShaderCannotTake)
{
    std::string nine = kHead;
    for (int i = 0; i < 9; ++i)
        nine += light(10.0, 40.0 * i);
    EXPECT_NE(loadErrorOfText("nine.toml", nine).find("light: at most 8 lights"), std::string::npos)
        << loadErrorOfText("nine.toml", nine);
    std::string eight = kHead;
    for (int i = 0; i < 8; ++i)
        eight += light(10.0, 40.0 * i);
    EXPECT_EQ(skyOf("eight.toml", eight).lights.size(), 8u);

    const std::string high = loadErrorOfText("high.toml", kHead + light(91.0, 0.0));
    EXPECT_NE(high.find("elevation_deg"), std::string::npos) << high;
    const std::string typo = loadErrorOfText("typo.toml", kHead + light(10.0, 0.0, "illuminance = 3.0\n"));
    EXPECT_NE(typo.find("illuminance"), std::string::npos) << typo;
    const std::string steps = loadErrorOfText("steps.toml", kHead + "[sky]\nview_steps = 0\n");
    EXPECT_NE(steps.find("view_steps"), std::string::npos) << steps;
    const std::string method = loadErrorOfText("method.toml", kHead + "[sky]\nlight_method = \"exact\"\n");
    EXPECT_NE(method.find("light_method"), std::string::npos) << method;
}
