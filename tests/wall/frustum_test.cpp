// The off-axis frustum (Kooima 2008): screen corners land on the NDC corners.
#include "wall/frustum.h"
#include "wall/wall.h"
#include "wall/wall_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace aurorawall::wall {
namespace {

glm::dvec3 toNdc(const Frustum& f, glm::dvec3 point)
{
    const glm::dvec4 clip = f.projection * f.view * glm::dvec4(point, 1.0);
    return glm::dvec3(clip) / clip.w;
}

void expectCornersOnNdcCorners(const Wall& wall, glm::dvec3 eye)
{
    for (const Screen& s : wall.screens) {
        SCOPED_TRACE(wall.sourceFile + " screen " + s.name);
        const Frustum f = offAxisFrustum(s, eye, 1.0, 1e5);
        const struct {
            glm::dvec3 corner;
            glm::dvec2 ndc;
        } corners[] = {{s.lowerLeft(), {-1, -1}}, {s.lowerRight(), {1, -1}}, {s.upperLeft(), {-1, 1}}, {s.upperRight(), {1, 1}}};
        for (const auto& c : corners) {
            const glm::dvec3 ndc = toNdc(f, c.corner);
            EXPECT_NEAR(ndc.x, c.ndc.x, 1e-12);
            EXPECT_NEAR(ndc.y, c.ndc.y, 1e-12);
            EXPECT_GT(ndc.z, -1.0);
            EXPECT_LT(ndc.z, 1.0);
        }
    }
}

TEST(Frustum, CornersOfEveryShippedScreenLandOnNdcCorners)
{
    for (const char* name : {"desktop-2x2.toml", "single.toml", "uaf-powerwall.toml", "desktop-3x1.toml", "desktop-2x2-bezel.toml"}) {
        const Wall wall = loadWall(std::string(WALL_CONFIG_DIR) + "/" + name);
        expectCornersOnNdcCorners(wall, wall.eyeMm);
        // An eye far off to the side and low: every frustum is strongly asymmetric.
        expectCornersOnNdcCorners(wall, wall.eyeMm + glm::dvec3(-3000.0, -500.0, 100.0));
    }
}

TEST(Frustum, SingleScreenBenchmarkViewHasA70DegreeVerticalField)
{
    const Wall wall = loadWall(std::string(WALL_CONFIG_DIR) + "/single.toml");
    const Frustum f = offAxisFrustum(wall.screens[0], wall.eyeMm, 10.0, 1e4);
    const double fovDeg = glm::degrees(std::atan(f.top / f.nearPlane) - std::atan(f.bottom / f.nearPlane));
    EXPECT_NEAR(fovDeg, 70.0, 1e-9);
    EXPECT_NEAR(f.right / f.top, 1280.0 / 720.0, 1e-12);
    EXPECT_NEAR(f.left, -f.right, 1e-12);
}

TEST(Frustum, CentredEyeViewIsATranslation)
{
    const Wall wall = loadWall(std::string(WALL_CONFIG_DIR) + "/single.toml");
    const Frustum f = offAxisFrustum(wall.screens[0], wall.eyeMm, 10.0, 1e4);
    const glm::dvec4 eyeInView = f.view * glm::dvec4(wall.eyeMm, 1.0);
    EXPECT_NEAR(glm::length(glm::dvec3(eyeInView)), 0.0, 1e-12);
    // The screen's centre is straight ahead, down -z.
    const glm::dvec4 centre = f.view * glm::dvec4(160.0, 90.0, 0.0, 1.0);
    EXPECT_NEAR(centre.x, 0.0, 1e-12);
    EXPECT_NEAR(centre.y, 0.0, 1e-12);
    EXPECT_NEAR(centre.z, -wall.eyeMm.z, 1e-12);
}

TEST(Frustum, EyeOnOrBehindTheScreenIsRejected)
{
    const Wall wall = loadWall(std::string(WALL_CONFIG_DIR) + "/single.toml");
    EXPECT_THROW(offAxisFrustum(wall.screens[0], {160, 90, 0}, 1.0, 10.0), std::invalid_argument);
    EXPECT_THROW(offAxisFrustum(wall.screens[0], {160, 90, -100}, 1.0, 10.0), std::invalid_argument);
    EXPECT_THROW(offAxisFrustum(wall.screens[0], {160, 90, 100}, 10.0, 1.0), std::invalid_argument);
}

} // namespace
} // namespace aurorawall::wall
