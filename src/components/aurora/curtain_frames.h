#pragma once
// The curtains at one moment of the animation, computed on the CPU in double precision from the
// scene's keyframes: between two keys every quantity moves with the C1 ease of
// aurora::smoothWeight (control points along great circles, energy geometrically, flux and
// detail phase linearly); before the first key and after the last the curtain holds still.
#include "components/aurora/aurora.h"

#include <glm/glm.hpp>

#include <vector>

namespace aurorawall::components::aurora {

struct CurtainState {
    std::vector<glm::dvec2> controlPointsLatLonDeg;
    double energyFluxErgPerCm2S = 0.0; // peak, after pulsation
    double energyKeV = 0.0;
    double detailPhase = 0.0;          // which fluid frame: 0 smooth ... 1 turbulent
    double detailOffsetKm = 0.0;       // drift of the detail along the curtain, reduced modulo the strip
};

// stripLengthKm: the period of the detail pattern along the curtain (the drift is reduced modulo
// it in double, so 1e9 s of drift keeps full float precision on the GPU).
CurtainState curtainAt(const Curtain& curtain, double timeS, double stripLengthKm);

} // namespace aurorawall::components::aurora
