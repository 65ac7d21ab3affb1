#pragma once
// What every rank must agree on to draw one frame. The master (rank 0) decides it and
// broadcasts it; the other ranks never read input or clocks of their own.
#include <glm/glm.hpp>

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

} // namespace aurorawall::cluster
