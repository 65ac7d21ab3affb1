#pragma once
// The curtains of a scene as one CPU model, used by the renderer's curtain field and by the CPU
// reference alike: at an animation time, each curtain's keyframes (curtain_frames.h) sampled into
// a dense polyline on the sphere, its peak flux, electron energy and fluid-detail offset and phase;
// and each curtain's lateral shape: how the profile is scaled across it and how far from its centre
// line it emits (its reach, also the radius of the rounded cap beyond each end). With fluid detail the
// strip is sampled at u * sigma_sim / sigma_curtain and emits within the reach of the frames its detail
// phase blends, scaled the same way; without, the profile is a Gaussian exp(-(u / sigma)^2 / 2), cut off
// at 4 sigma (sigma = thickness / 2).
#include "components/aurora/physics/curtain_geometry.h"
#include "components/aurora/aurora.h"
#include "components/aurora/curtain_frames.h"
#include "components/roles/curtain_detail.h"

#include <optional>
#include <vector>

namespace aurorawall::components::aurora {

struct CurtainNow {
    physics::CurtainPolyline polyline;
    CurtainState state;
    double lateralScale = 0.0; // profile coordinate per km across the curtain
    double reachKm = 0.0;      // beyond this distance from its centre line (and its ends) it does not emit
};

class CurtainModel {
public:
    // detail: the curtain detail frames' shape, or null when the scene lists no provider of it.
    CurtainModel(const Settings& aurora, double planetRadiusKm, const roles::DetailShape* detail);

    // Every curtain at animation time timeS, in the scene's order: statesAt, then footprint of each.
    std::vector<CurtainNow> at(double timeS) const;
    // Every curtain's keyframed state at timeS (cheap: no spline sampling), in the scene's order.
    std::vector<CurtainState> statesAt(double timeS) const;
    // The dense polyline of a state's control points: a function of those points alone.
    physics::CurtainPolyline footprint(const CurtainState& state) const;
    // Profile coordinate per km across curtain i.
    double lateralScale(size_t i) const { return lateralScale_[i]; }
    // Beyond this distance from its centre line and its ends (km on the ground) curtain i does not emit
    // at detail phase detailPhase.
    double reachKm(size_t i, double detailPhase) const;

    // The largest reach of any curtain at any phase: beyond it from every centre line nothing emits.
    double reachKm() const { return reachKm_; }
    const roles::DetailShape* detail() const { return detail_ ? &*detail_ : nullptr; }
    const Settings& settings() const { return aurora_; }
    double planetRadiusKm() const { return planetRadiusKm_; }

private:
    const Settings& aurora_;
    double planetRadiusKm_;
    std::optional<roles::DetailShape> detail_;
    std::vector<double> lateralScale_;
    double reachKm_ = 0.0;
};

} // namespace aurorawall::components::aurora
