#include "wall/tile_rays.h"

#include "physics/constants.h"
#include "common/glsl.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace aurorawall::wall {
namespace {

namespace f64 {
AURORAWALL_GLSL_PRECISION(double)
#include "render/fisheye.glsl"
} // namespace f64

// The dome master's constants, from the whole canvas so that every tile agrees (tile_rays.h).
void setDome(TileRays& rays, const Wall& wall)
{
    const double tilt = wall.dome.tiltDeg * physics::kDegree;
    rays.dome = true;
    rays.domeCentrePx = glm::dvec2(wall.canvasSizePx) / 2.0;
    rays.domeRadiusPx = wall.canvasSizePx.y / 2.0;
    rays.domeRadiansPerPx = wall.dome.fieldOfViewDeg * physics::kDegree / 2.0 / rays.domeRadiusPx;
    rays.domeAxis = {0.0, std::sin(tilt), -std::cos(tilt)};
    rays.domeRight = {1.0, 0.0, 0.0};
    rays.domeDown = {0.0, -std::cos(tilt), -std::sin(tilt)};
}

} // namespace

TileRays tileRays(const Wall& wall, int screenIndex, glm::ivec2 regionOffsetPx)
{
    if (screenIndex < 0 || screenIndex >= int(wall.screens.size()))
        throw std::out_of_range("tileRays: no screen " + std::to_string(screenIndex));
    const Screen& s = wall.screens[screenIndex];
    const glm::dvec3 eye = wall.eyeOf(s);
    TileRays rays;
    if (s.eye == Eye::sideBySide) {
        rays.stepRight = 2.0 * (s.lowerRight() - s.lowerLeft()) / double(s.widthPx);
        rays.stepDown = (s.lowerLeft() - s.upperLeft()) / double(s.heightPx);
        rays.originDir = s.upperLeft() - wall.eyePosition(Eye::left);
        rays.originDirRight = s.upperLeft() - wall.eyePosition(Eye::right) - (s.lowerRight() - s.lowerLeft());
        rays.splitPx = s.widthPx / 2;
        rays.pixelOffset = regionOffsetPx;
    } else if (wall.sharedCanvas) {
        // One origin and one pair of steps for every screen of an eye: only the integer offset differs.
        rays.stepRight = {wall.canvasPitchMm.x, 0.0, 0.0};
        rays.stepDown = {0.0, -wall.canvasPitchMm.y, 0.0};
        const double shiftPx = s.eye == Eye::right ? wall.rightEyeCanvasShiftPx : 0;
        rays.originDir = glm::dvec3(wall.canvasTopLeftMm, 0.0) - eye - shiftPx * rays.stepRight;
        rays.pixelOffset = s.canvasOffsetPx + regionOffsetPx;
    } else {
        rays.originDir = s.upperLeft() - eye;
        rays.stepRight = (s.lowerRight() - s.lowerLeft()) / double(s.widthPx);
        rays.stepDown = (s.lowerLeft() - s.upperLeft()) / double(s.heightPx);
        rays.pixelOffset = regionOffsetPx;
    }
    if (wall.projection == Projection::dome) {
        rays.pixelOffset = s.canvasOffsetPx + regionOffsetPx;
        setDome(rays, wall);
    }
    return rays;
}

double tanHalfVerticalFieldOfView(const Wall& wall)
{
    double bottom = wall.screens.front().lowerLeftMm.y, top = bottom;
    for (const Screen& s : wall.screens) {
        bottom = std::min(bottom, s.lowerLeftMm.y);
        top = std::max(top, s.lowerLeftMm.y + s.heightMm);
    }
    return 0.5 * (top - bottom) / wall.eyeMm.z;
}

glm::dvec3 domeDirection(const TileRays& rays, glm::dvec2 canvasPx)
{
    const glm::dvec2 offset = canvasPx - rays.domeCentrePx;
    if (!f64::insideFisheye(offset, rays.domeRadiusPx))
        return glm::dvec3(0.0);
    return f64::fisheyeDirection(offset, rays.domeRadiansPerPx, rays.domeAxis, rays.domeRight, rays.domeDown);
}

} // namespace aurorawall::wall
