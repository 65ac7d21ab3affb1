#include "scene/camera_path.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace aurorawall::scene {

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
    if (timeS <= keys_.front().timeS)
        return keys_.front().positionKm;
    if (timeS >= keys_.back().timeS)
        return keys_.back().positionKm;
    double s = 0.0;
    const std::size_t i = segment(timeS, s);
    const double h = keys_[i + 1].timeS - keys_[i].timeS;
    // Cubic Hermite basis (e.g. Kochanek & Bartels 1984): p(s) = h00 p0 + h10 h m0 + h01 p1 + h11 h m1.
    const double s2 = s * s, s3 = s2 * s;
    const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
    return h00 * keys_[i].positionKm + h10 * h * tangentsKmPerS_[i] + h01 * keys_[i + 1].positionKm +
           h11 * h * tangentsKmPerS_[i + 1];
}

glm::dquat CameraPath::orientationAt(double timeS) const
{
    if (timeS <= keys_.front().timeS)
        return keys_.front().orientation;
    if (timeS >= keys_.back().timeS)
        return keys_.back().orientation;
    double s = 0.0;
    const std::size_t i = segment(timeS, s);
    const glm::dquat& a = keys_[i].orientation;
    const glm::dquat& b = keys_[i + 1].orientation; // dot(a, b) >= 0: the short arc
    // Slerp (Shoemake 1985): sin((1-s) theta)/sin theta a + sin(s theta)/sin theta b; nearly equal
    // keys (theta below 1e-6 rad) use the normalised linear blend, which it equals to O(theta^2).
    const double cosTheta = std::min(1.0, glm::dot(a, b));
    const double theta = std::acos(cosTheta);
    if (theta < 1e-6)
        return glm::normalize((1.0 - s) * a + s * b);
    const double sinTheta = std::sin(theta);
    return (std::sin((1.0 - s) * theta) / sinTheta) * a + (std::sin(s * theta) / sinTheta) * b;
}

} // namespace aurorawall::scene
