#include "scene/camera_path.h"

#include "physics/constants.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace aurorawall::scene {

namespace {

// The logarithm of a unit quaternion q = (cos(a/2), sin(a/2) n): the vector (a/2) n, a in [0, 2 pi].
// atan2 keeps it accurate for small angles, where acos of the real part loses half the digits.
glm::dvec3 logOf(const glm::dquat& q)
{
    const glm::dvec3 v(q.x, q.y, q.z);
    const double sinHalf = glm::length(v);
    if (sinHalf == 0.0)
        return glm::dvec3(0.0);
    return v * (std::atan2(sinHalf, q.w) / sinHalf);
}

// The inverse of logOf: exp(v) = (cos |v|, sin |v| v / |v|), a unit quaternion.
glm::dquat expOf(const glm::dvec3& v)
{
    const double half = glm::length(v);
    if (half == 0.0)
        return {1.0, 0.0, 0.0, 0.0};
    const glm::dvec3 u = v * (std::sin(half) / half);
    return {std::cos(half), u.x, u.y, u.z};
}

// Slerp (Shoemake 1985) as a exp(s log(a* b)): from a (s = 0, exactly) to b (s = 1) at a constant
// angular rate. b is taken as given, not negated to the short arc: SQUAD's inner blends must join
// their own quaternions for the spline to stay continuous.
glm::dquat slerp(const glm::dquat& a, const glm::dquat& b, double s)
{
    return a * expOf(s * logOf(glm::conjugate(a) * b));
}

// The cubic Hermite basis (e.g. Kochanek & Bartels 1984) at s in [0, 1] of a segment of length h:
// f(s) = h00 f0 + h10 h m0 + h01 f1 + h11 h m1 for values f and time derivatives m at its ends.
struct Hermite {
    double h00, h10, h01, h11;
};

Hermite hermite(double s)
{
    const double s2 = s * s, s3 = s2 * s;
    return {2 * s3 - 3 * s2 + 1, s3 - 2 * s2 + s, -2 * s3 + 3 * s2, s3 - s2};
}

// The end key whose values hold at timeS when timeS is at or beyond that end of the path; null
// between the ends.
const CameraKey* endKeyAt(const std::vector<CameraKey>& keys, double timeS)
{
    return timeS <= keys.front().timeS ? &keys.front() : timeS >= keys.back().timeS ? &keys.back() : nullptr;
}

} // namespace

double zoomOf(double fieldOfViewDeg, double wallTanHalfFov)
{
    return wallTanHalfFov / std::tan(0.5 * fieldOfViewDeg * physics::kDegree);
}

double zoomOf(const CameraKey& key, double wallTanHalfFov)
{
    return key.fieldOfViewDeg > 0.0 ? zoomOf(key.fieldOfViewDeg, wallTanHalfFov) : key.zoom;
}

glm::dquat orientationOf(const CameraFrame& frame)
{
    const glm::dvec3 right = glm::cross(frame.forward, frame.up);
    return glm::normalize(glm::quat_cast(glm::dmat3(right, frame.up, -frame.forward)));
}

CameraFrame frameOf(const glm::dquat& orientation)
{
    const glm::dmat3 axes = glm::mat3_cast(orientation);
    return {-axes[2], axes[1]};
}

CameraPath::CameraPath(std::vector<CameraKey> keys) : keys_(std::move(keys))
{
    if (keys_.size() < 2)
        throw std::invalid_argument("a camera path needs at least 2 keys");
    for (std::size_t i = 1; i < keys_.size(); ++i) {
        if (!(keys_[i].timeS > keys_[i - 1].timeS))
            throw std::invalid_argument("camera path keys must be in increasing time");
        // q and -q are the same rotation; take the one nearer the previous key (no flip).
        if (glm::dot(keys_[i].orientation, keys_[i - 1].orientation) < 0.0)
            keys_[i].orientation = -keys_[i].orientation;
    }
    // Tangents: the centred difference (p[i+1] - p[i-1]) / (t[i+1] - t[i-1]) inside (Catmull-Rom in
    // time), the one-sided difference at the ends. Both are exact for motion at constant velocity.
    const std::size_t n = keys_.size();
    tangentsKmPerS_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const CameraKey& a = keys_[i == 0 ? 0 : i - 1];
        const CameraKey& b = keys_[i + 1 == n ? i : i + 1];
        tangentsKmPerS_[i] = (b.positionKm - a.positionKm) / (b.timeS - a.timeS);
    }
    // Orientations: q(t) = q_i exp(w t) near key i has dq/dt = q_i w, w the angular velocity in the
    // camera's frame over 2 (logOf's half angles). Segment i turns at the constant rate
    // L_i / h_i under slerp, L_i = log(q_i* q_{i+1}), h_i = t_{i+1} - t_i. The key's rate W_i is
    // (L_{i-1} + L_i) / (h_{i-1} + h_i) inside, the same time weighting as the positions' centred
    // difference, and the end segment's own rate at the first and the last key (clamped ends: there
    // SQUAD is slerp's start or end).
    std::vector<glm::dvec3> chords(n - 1), rates(n);
    for (std::size_t i = 0; i + 1 < n; ++i)
        chords[i] = logOf(glm::conjugate(keys_[i].orientation) * keys_[i + 1].orientation);
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t a = i == 0 ? 0 : i - 1, b = i + 1 == n ? i : i + 1;
        glm::dvec3 turn(0.0); // from key a to key b, in key i's frame
        for (std::size_t k = a; k < b; ++k)
            turn += chords[k];
        rates[i] = turn / (keys_[b].timeS - keys_[a].timeS);
    }
    // SQUAD(s) = slerp(slerp(q_i, q_{i+1}, s), slerp(A_i, B_{i+1}, s), 2 s (1 - s)) has the rates
    // q_i* dq/ds = L_i + 2 log(q_i* A_i) at s = 0 and q_{i+1}* dq/ds = L_i - 2 log(q_{i+1}* B_{i+1})
    // at s = 1. Setting both to h_i W gives A_i = q_i exp((h_i W_i - L_i) / 2) and
    // B_{i+1} = q_{i+1} exp((L_i - h_i W_{i+1}) / 2): dq/dt is the same on both sides of every key.
    // With equal spacing both are Shoemake's q_i exp(-(log(q_i* q_{i+1}) + log(q_i* q_{i-1})) / 4),
    // which with uneven spacing would leave a jump in angular velocity of order (h_i - h_{i-1}) / h.
    leaving_.resize(n);
    arriving_.resize(n);
    for (std::size_t i = 0; i + 1 < n; ++i) {
        const double h = keys_[i + 1].timeS - keys_[i].timeS;
        leaving_[i] = keys_[i].orientation * expOf(0.5 * (h * rates[i] - chords[i]));
        arriving_[i + 1] = keys_[i + 1].orientation * expOf(0.5 * (chords[i] - h * rates[i + 1]));
    }
}

std::size_t CameraPath::segment(double timeS, double& s) const
{
    const auto after = std::upper_bound(keys_.begin(), keys_.end(), timeS,
                                        [](double t, const CameraKey& k) { return t < k.timeS; });
    const std::size_t i = static_cast<std::size_t>(after - keys_.begin()) - 1; // keys_[i].timeS <= timeS
    s = (timeS - keys_[i].timeS) / (keys_[i + 1].timeS - keys_[i].timeS);
    return i;
}

glm::dvec3 CameraPath::positionAt(double timeS) const
{
    if (const CameraKey* end = endKeyAt(keys_, timeS))
        return end->positionKm;
    double s = 0.0;
    const std::size_t i = segment(timeS, s);
    const double h = keys_[i + 1].timeS - keys_[i].timeS;
    const Hermite b = hermite(s);
    return b.h00 * keys_[i].positionKm + b.h10 * h * tangentsKmPerS_[i] + b.h01 * keys_[i + 1].positionKm +
           b.h11 * h * tangentsKmPerS_[i + 1];
}

double CameraPath::zoomAt(double timeS, double wallTanHalfFov) const
{
    const auto zoom = [&](std::size_t k) { return zoomOf(keys_[k], wallTanHalfFov); };
    if (const CameraKey* end = endKeyAt(keys_, timeS))
        return zoomOf(*end, wallTanHalfFov);
    double s = 0.0;
    const std::size_t i = segment(timeS, s);
    if (s == 0.0) // exactly the key's zoom, not exp(ln z) rounded
        return zoom(i);
    // ln z with the positions' tangents: the centred difference inside, one-sided at the ends.
    const std::size_t n = keys_.size();
    const auto tangent = [&](std::size_t k) {
        const std::size_t a = k == 0 ? 0 : k - 1, b = k + 1 == n ? k : k + 1;
        return (std::log(zoom(b)) - std::log(zoom(a))) / (keys_[b].timeS - keys_[a].timeS);
    };
    const double h = keys_[i + 1].timeS - keys_[i].timeS;
    const Hermite b = hermite(s);
    return std::exp(b.h00 * std::log(zoom(i)) + b.h10 * h * tangent(i) + b.h01 * std::log(zoom(i + 1)) +
                    b.h11 * h * tangent(i + 1));
}

CameraFrame CameraPath::frameAt(double timeS) const
{
    const auto at = std::lower_bound(keys_.begin(), keys_.end(), timeS,
                                     [](const CameraKey& k, double t) { return k.timeS < t; });
    const CameraKey* key = endKeyAt(keys_, timeS);
    if (!key && at != keys_.end() && at->timeS == timeS)
        key = &*at;
    if (key && key->frame)
        return *key->frame;
    return frameOf(orientationAt(timeS));
}

glm::dquat CameraPath::orientationAt(double timeS) const
{
    if (const CameraKey* end = endKeyAt(keys_, timeS))
        return end->orientation;
    double s = 0.0;
    const std::size_t i = segment(timeS, s);
    const glm::dquat along = slerp(keys_[i].orientation, keys_[i + 1].orientation, s);
    const glm::dquat inner = slerp(leaving_[i], arriving_[i + 1], s);
    return slerp(along, inner, 2.0 * s * (1.0 - s));
}

} // namespace aurorawall::scene
