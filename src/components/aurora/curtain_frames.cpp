#include "components/aurora/curtain_frames.h"

#include "components/aurora/physics/curtain_geometry.h"
#include "physics/constants.h"

#include <algorithm>
#include <cmath>

namespace aurorawall::components::aurora {

CurtainState curtainAt(const Curtain& curtain, double timeS, double stripLengthKm)
{
    const std::vector<CurtainKey>& keys = curtain.keys;
    // The last key at or before timeS, and the one after it (the same one at the ends).
    const auto after = std::upper_bound(keys.begin(), keys.end(), timeS,
                                        [](double t, const CurtainKey& k) { return t < k.timeS; });
    const CurtainKey& a = after == keys.begin() ? keys.front() : *(after - 1);
    const CurtainKey& b = after == keys.end() ? keys.back() : *after;
    const double w = (&a == &b) ? 0.0 : physics::smoothWeight(timeS, a.timeS, b.timeS);

    CurtainState s;
    s.controlPointsLatLonDeg = w == 0.0 ? a.pointsLatLonDeg
                                        : physics::interpolateControlPoints(a.pointsLatLonDeg, b.pointsLatLonDeg, w);
    s.energyKeV = a.energyKeV * std::pow(b.energyKeV / a.energyKeV, w);
    s.energyFluxErgPerCm2S = a.energyFluxErgPerCm2S + w * (b.energyFluxErgPerCm2S - a.energyFluxErgPerCm2S);
    s.detailPhase = a.detailPhase + w * (b.detailPhase - a.detailPhase);
    // Pulsating aurora: a raised-cosine dimming with the given period; the phase is reduced in double.
    if (curtain.pulsationPeriodS > 0.0) {
        const double cycle = std::fmod(timeS / curtain.pulsationPeriodS, 1.0);
        s.energyFluxErgPerCm2S *= 1.0 - curtain.pulsationDepth * 0.5 * (1.0 - std::cos(2.0 * aurorawall::physics::kPi * cycle));
    }
    const double offset = std::fmod(curtain.driftKmPerS * timeS, stripLengthKm);
    s.detailOffsetKm = offset < 0.0 ? offset + stripLengthKm : offset;
    return s;
}

} // namespace aurorawall::components::aurora
