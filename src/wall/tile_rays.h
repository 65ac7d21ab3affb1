#pragma once
// Pixel rays for the raymarcher. The direction (unnormalized, wall frame) from the eye through the
// point at continuous canvas coordinate (px, py) -- x right, y down, pixel centres at integer + 0.5 --
// is originDir + px*stepRight + py*stepDown, where (px, py) = pixelOffset + the tile-local coordinate.
//
// On a shared canvas (wall.h) every screen gets the same originDir, stepRight and stepDown, computed
// once from the canvas's top-left corner, and differs only in the integer pixelOffset. The GPU then
// evaluates the same float expression for the same canvas coordinate on both sides of a seam, so
// adjacent tiles compute bit-identical edge rays. Without a shared canvas each screen uses its own
// upper-left corner as origin and its own pixel steps. Each screen's rays start at the eye it
// shows (Wall::eyeOf); on a stereo canvas the right eye's originDir undoes its canvas shift.
// A side-by-side screen uses its own geometry with steps of two physical pixels across: columns
// below splitPx start at the left eye (originDir), the others at the right eye (originDirRight,
// which already subtracts the screen's width so that column splitPx lands on its left edge).
//
// A dome master (Projection::dome) ignores the physical geometry: the canvas coordinate's offset
// from the canvas centre goes through the angular fisheye of shaders/render/fisheye.glsl, with
// domeRadiansPerPx = (field of view / 2) / (canvas height / 2). The circle of radius half the canvas
// height holds the image; pixels outside it are black. The dome's frame in the wall frame (the
// camera looks along -z, up is +y): axis = (0, sin t, -cos t) for tilt t, right = +x, down =
// (0, -cos t, -sin t), so the image is the view seen from inside the dome, the axis's up-side on top.
#include "wall/wall.h"

#include <glm/glm.hpp>

namespace aurorawall::wall {

struct TileRays {
    glm::dvec3 originDir;   // eye -> canvas (or screen) top-left corner, mm
    glm::dvec3 stepRight;   // one pixel to the right, mm
    glm::dvec3 stepDown;    // one pixel down, mm
    glm::ivec2 pixelOffset; // canvas coordinate of the tile's top-left pixel corner
    double splitPx = 1e30;     // side by side: the first coordinate of the right eye's half
    glm::dvec3 originDirRight{0.0};

    bool dome = false;              // the dome master's fisheye instead of the three vectors above
    glm::dvec2 domeCentrePx{0.0};   // canvas coordinate of the image centre
    double domeRadiusPx = 0.0;      // the image circle: half the canvas height
    double domeRadiansPerPx = 0.0;  // angle from the axis per pixel of distance from the centre
    glm::dvec3 domeAxis{0.0}, domeRight{0.0}, domeDown{0.0}; // orthonormal, wall frame
};

// Rays of the screen wall.screens[screenIndex], or of its sub-rectangle whose top-left pixel is
// regionOffsetPx inside the screen.
TileRays tileRays(const Wall& wall, int screenIndex, glm::ivec2 regionOffsetPx = {0, 0});

// tan(W/2) of the wall's own vertical field of view W at its eye: half the height of the screens'
// bounding box (bezels included) over the eye's distance from the wall plane, so W is the angle the
// wall spans seen from in front of its centre. A camera path's field of view zooms the flat wall's
// rays relative to it (scene/camera_path.h, cluster::wallToPlanet); a dome master keeps its own
// field of view and ignores the zoom.
double tanHalfVerticalFieldOfView(const Wall& wall);

// Unit direction (wall frame) of the dome master's pixel at continuous canvas coordinate canvasPx,
// in double; the zero vector outside the image circle.
glm::dvec3 domeDirection(const TileRays& rays, glm::dvec2 canvasPx);

// The shader's evaluation in precision T (float on the GPU): the direction through tile-local
// continuous coordinate localPx. Every input is rounded to T first, as uniforms are.
template <typename T>
glm::vec<3, T> rayDirection(const TileRays& rays, glm::vec<2, T> localPx)
{
    using Vec3 = glm::vec<3, T>;
    const glm::vec<2, T> canvasPx = glm::vec<2, T>(rays.pixelOffset) + localPx;
    const Vec3 origin(canvasPx.x >= T(rays.splitPx) ? rays.originDirRight : rays.originDir);
    return origin + canvasPx.x * Vec3(rays.stepRight) + canvasPx.y * Vec3(rays.stepDown);
}

} // namespace aurorawall::wall
