#pragma once
// Pixel rays for the raymarcher. The direction (unnormalized, wall frame) from the eye through the
// point at continuous canvas coordinate (px, py) -- x right, y down, pixel centres at integer + 0.5 --
// is originDir + px*stepRight + py*stepDown, where (px, py) = pixelOffset + the tile-local coordinate.
//
// On a shared canvas (wall.h) every screen gets the same originDir, stepRight and stepDown, computed
// once from the canvas's top-left corner, and differs only in the integer pixelOffset. The GPU then
// evaluates the same float expression for the same canvas coordinate on both sides of a seam, so
// adjacent tiles compute bit-identical edge rays. Without a shared canvas each screen uses its own
// upper-left corner as origin and its own pixel steps.
#include "wall/wall.h"

#include <glm/glm.hpp>

namespace aurorawall::wall {

struct TileRays {
    glm::dvec3 originDir;   // eye -> canvas (or screen) top-left corner, mm
    glm::dvec3 stepRight;   // one pixel to the right, mm
    glm::dvec3 stepDown;    // one pixel down, mm
    glm::ivec2 pixelOffset; // canvas coordinate of the tile's top-left pixel corner
};

// Rays of the screen wall.screens[screenIndex], or of its sub-rectangle whose top-left pixel is
// regionOffsetPx inside the screen.
TileRays tileRays(const Wall& wall, int screenIndex, glm::ivec2 regionOffsetPx = {0, 0});

// The shader's evaluation in precision T (float on the GPU): the direction through tile-local
// continuous coordinate localPx. Every input is rounded to T first, as uniforms are.
template <typename T>
glm::vec<3, T> rayDirection(const TileRays& rays, glm::vec<2, T> localPx)
{
    using Vec3 = glm::vec<3, T>;
    const glm::vec<2, T> canvasPx = glm::vec<2, T>(rays.pixelOffset) + localPx;
    return Vec3(rays.originDir) + canvasPx.x * Vec3(rays.stepRight) + canvasPx.y * Vec3(rays.stepDown);
}

} // namespace aurorawall::wall
