#pragma once
// A keyed camera flight: positions and orientations at given animation times, interpolated in
// double. Positions follow a cubic Hermite spline whose tangents are finite differences of the
// neighbouring keys (one-sided at the ends), so the position and the velocity are continuous (C1)
// and keys on a straight line at constant speed give that line exactly. Orientations are unit
// quaternions joined by a SQUAD spline (Shoemake 1987) whose control points are set from
// time-weighted tangents, so the orientation and the angular velocity are continuous (C1) at every
// key, for uneven key times too (camera_path.cpp gives the construction). Each key's quaternion is
// first made to lie in the same hemisphere as the previous one (non-negative dot product), so the
// camera turns the short way between keys and never flips. Before the first key and after the last
// the camera holds still. The path is a function of animation time alone: it plays the same at any
// frame rate.
//
// A key may set a vertical field of view; the wall shows it as a zoom z = tan(W/2) / tan(F/2) about
// its eye, W the wall's own vertical field of view (wall/tile_rays.h), F the key's. A key may give
// the zoom itself instead (what `render --record-path` writes: it reads back exactly); a key with
// neither has z = 1. Between keys ln z follows the positions' cubic Hermite spline (tangents from the
// same finite differences), so the zoom is C1, geometric (constant ln-rate between keys of evenly
// spaced ln z) and never <= 0.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <optional>
#include <vector>

namespace aurorawall::scene {

// A camera orientation: forward (where it looks) and up, orthonormal.
struct CameraFrame {
    glm::dvec3 forward{0.0, 1.0, 0.0};
    glm::dvec3 up{0.0, 0.0, 1.0};
};

// The rotation taking the camera's axes (right, up, back = -forward) to the planet frame.
glm::dquat orientationOf(const CameraFrame& frame);
CameraFrame frameOf(const glm::dquat& orientation);

struct CameraKey {
    double timeS = 0.0;           // animation time, s
    glm::dvec3 positionKm{0.0};   // planet frame, km
    glm::dquat orientation{1.0, 0.0, 0.0, 0.0};
    std::optional<CameraFrame> frame = std::nullopt; // the orientation as read: the path's frame at the key's time, bit for bit
    double fieldOfViewDeg = 0.0;  // vertical, in (0, 180); 0: none, the zoom below instead
    double zoom = 1.0;            // > 0, relative to the wall's own view; used without a field of view
};

// The zoom that shows a vertical field of view fieldOfViewDeg on a wall whose own vertical field of
// view W has tan(W/2) = wallTanHalfFov: tan(W/2) / tan(F/2).
double zoomOf(double fieldOfViewDeg, double wallTanHalfFov);
// A key's zoom: zoomOf its field of view if it gives one, else its zoom.
double zoomOf(const CameraKey& key, double wallTanHalfFov);

class CameraPath {
public:
    CameraPath() = default;
    // At least 2 keys with strictly increasing times (the scene reader checks and reports).
    explicit CameraPath(std::vector<CameraKey> keys);

    bool empty() const { return keys_.empty(); }
    const std::vector<CameraKey>& keys() const { return keys_; }

    glm::dvec3 positionAt(double timeS) const;
    glm::dquat orientationAt(double timeS) const;
    // The camera's axes at timeS: at a key's time (or beyond the ends) that key's frame as read, so a
    // recorded flight replays its frames bit for bit; elsewhere frameOf(orientationAt(timeS)).
    CameraFrame frameAt(double timeS) const;
    // The zoom at timeS on a wall whose vertical field of view W has tan(W/2) = wallTanHalfFov; exactly
    // each key's zoomOf at its time, held before the first key and after the last.
    double zoomAt(double timeS, double wallTanHalfFov) const;

private:
    // The index i of the segment [key i, key i+1] holding timeS, and its fraction s in [0, 1).
    std::size_t segment(double timeS, double& s) const;

    std::vector<CameraKey> keys_;
    std::vector<glm::dvec3> tangentsKmPerS_; // dp/dt at each key
    // SQUAD's inner control points: leaving[i] starts segment i, arriving[i] ends segment i - 1.
    std::vector<glm::dquat> leaving_;
    std::vector<glm::dquat> arriving_;
};

} // namespace aurorawall::scene
