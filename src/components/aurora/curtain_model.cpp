#include "components/aurora/curtain_model.h"

#include <algorithm>

namespace aurorawall::components::aurora {

CurtainModel::CurtainModel(const Settings& aurora, double planetRadiusKm, const fluid_detail::DetailShape* detail)
    : aurora_(aurora), planetRadiusKm_(planetRadiusKm)
{
    if (detail)
        detail_ = *detail;
    for (const Curtain& c : aurora.curtains) {
        const double sigma = 0.5 * c.thicknessKm;
        const double scale = detail ? detail->fluxWidthKm / sigma : 1.0 / sigma;
        lateralScale_.push_back(scale);
        reachKm_ = std::max(reachKm_, detail ? detail->reachKm / scale : 4.0 * sigma);
    }
}

std::vector<CurtainNow> CurtainModel::at(double timeS) const
{
    const double stripLength = detail_ ? detail_->stripLengthKm : 1.0;
    std::vector<CurtainNow> now;
    for (size_t i = 0; i < aurora_.curtains.size(); ++i) {
        CurtainNow c;
        c.state = curtainAt(aurora_.curtains[i], timeS, stripLength);
        c.polyline = physics::sampleCurtain(c.state.controlPointsLatLonDeg, planetRadiusKm_,
                                                         aurora_.polylineSpacingKm);
        c.lateralScale = lateralScale_[i];
        now.push_back(std::move(c));
    }
    return now;
}

} // namespace aurorawall::components::aurora
