#pragma once
// What every rank must agree on to draw one frame. The master (rank 0) decides it and
// broadcasts it; the other ranks never read input or clocks of their own.
#include <glm/glm.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <type_traits>

namespace aurorawall::cluster {

struct FrameState {
    std::uint64_t frame = 0;
    double timeS = 0.0;                   // animation time, seconds (double: stays exact at 1e9 s)
    double nextTimeS = std::numeric_limits<double>::quiet_NaN(); // the time the next frame shows unless a
                                          // command changes it (pause, play, speed, step, time), for
                                          // ranks to prepare ahead; NaN: not known (a single frame)
    glm::dvec3 cameraPositionKm{0.0};     // planet frame
    glm::dvec3 cameraRight{1.0, 0.0, 0.0};
    glm::dvec3 cameraUp{0.0, 1.0, 0.0};
    glm::dvec3 cameraBack{0.0, 0.0, 1.0}; // the camera looks along -back
    double zoom = 1.0;                    // > 0: the wall's rays scaled about the eye (wallToPlanet)
    double exposure = 1.0;
    std::int32_t quit = 0;                // 1: this state is not rendered; every rank leaves the loop
    std::int32_t gatherWall = 0;          // 1: after drawing, every rank sends its screens to the master,
                                          // which assembles the wall (a screenshot or a movie frame)
};
static_assert(std::is_trivially_copyable_v<FrameState>, "FrameState is broadcast as bytes");

// The wall frame (x right, y up, z toward the viewer, from the eye) in the planet frame: the camera's
// axes, with x and y divided by the zoom z, so that the ray through the wall point p becomes
// (p.x / z, p.y / z, p.z) on every screen alike (a zoom of 2 shows the centre half of the view).
inline glm::dmat3 wallToPlanet(const FrameState& s)
{
    return glm::dmat3(s.cameraRight / s.zoom, s.cameraUp / s.zoom, s.cameraBack);
}

// Where this frame's rays start. The GPU holds positions in float, to 2^-24 of their size: 6 km at
// 1e8 km, far coarser than what a narrow view of the planet resolves from there. So a camera farther
// than twice `reachRadiusKm` (scene::Scene::reachRadiusKm) from the planet's centre moves every ray
// forward by distanceKm = |camera| - 2 reachRadiusKm, to a point at least 2 reachRadiusKm from the
// centre, while everything the scene draws lies at least |camera| - reachRadiusKm away: the ray of unit
// direction d starts at camera + distanceKm d = pointKm + distanceKm (d - forward), where pointKm
// comes from double here and d - forward, small across a narrow view, keeps its precision on the
// GPU (render/tile_rays.glsl).
// A nearer camera's rays start at the camera (distanceKm 0, pointKm the camera).
struct RayStart {
    glm::dvec3 pointKm;
    double distanceKm;
    glm::dvec3 forward; // unit, the camera's view direction
};

inline RayStart rayStart(const FrameState& s, double reachRadiusKm)
{
    const glm::dvec3 forward = -s.cameraBack;
    const double distance = std::max(0.0, glm::length(s.cameraPositionKm) - 2.0 * reachRadiusKm);
    return {s.cameraPositionKm + distance * forward, distance, forward};
}

} // namespace aurorawall::cluster
