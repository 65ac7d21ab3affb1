#include "components/aurora/curtain_model.h"

#include <algorithm>

namespace aurorawall::components::aurora {

CurtainModel::CurtainModel(const Settings& aurora, double planetRadiusKm, const roles::DetailShape* detail)
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

double CurtainModel::reachKm(size_t i, double detailPhase) const
{
    if (detail_)
        return detail_->reachAtPhaseKm(detailPhase) / lateralScale_[i];
    return 4.0 / lateralScale_[i];
}

std::vector<CurtainState> CurtainModel::statesAt(double timeS) const
{
    const double stripLength = detail_ ? detail_->stripLengthKm : 1.0;
    std::vector<CurtainState> states;
    for (const Curtain& c : aurora_.curtains)
        states.push_back(curtainAt(c, timeS, stripLength));
    return states;
}

physics::CurtainPolyline CurtainModel::footprint(const CurtainState& state) const
{
    return physics::sampleCurtain(state.controlPointsLatLonDeg, planetRadiusKm_, aurora_.polylineSpacingKm);
}

std::vector<CurtainNow> CurtainModel::at(double timeS) const
{
    std::vector<CurtainNow> now;
    std::vector<CurtainState> states = statesAt(timeS);
    for (size_t i = 0; i < states.size(); ++i) {
        CurtainNow c;
        c.polyline = footprint(states[i]);
        c.state = std::move(states[i]);
        c.lateralScale = lateralScale_[i];
        c.reachKm = reachKm(i, c.state.detailPhase);
        now.push_back(std::move(c));
    }
    return now;
}

} // namespace aurorawall::components::aurora
