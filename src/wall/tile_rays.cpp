#include "wall/tile_rays.h"

#include <stdexcept>

namespace aurorawall::wall {

TileRays tileRays(const Wall& wall, int screenIndex, glm::ivec2 regionOffsetPx)
{
    if (screenIndex < 0 || screenIndex >= int(wall.screens.size()))
        throw std::out_of_range("tileRays: no screen " + std::to_string(screenIndex));
    const Screen& s = wall.screens[screenIndex];
    TileRays rays;
    if (wall.sharedCanvas) {
        // One origin and one pair of steps for every screen: only the integer offset differs.
        rays.originDir = glm::dvec3(wall.canvasTopLeftMm, 0.0) - wall.eyeMm;
        rays.stepRight = {wall.canvasPitchMm.x, 0.0, 0.0};
        rays.stepDown = {0.0, -wall.canvasPitchMm.y, 0.0};
        rays.pixelOffset = s.canvasOffsetPx + regionOffsetPx;
    } else {
        rays.originDir = s.upperLeft() - wall.eyeMm;
        rays.stepRight = (s.lowerRight() - s.lowerLeft()) / double(s.widthPx);
        rays.stepDown = (s.lowerLeft() - s.upperLeft()) / double(s.heightPx);
        rays.pixelOffset = regionOffsetPx;
    }
    return rays;
}

} // namespace aurorawall::wall
