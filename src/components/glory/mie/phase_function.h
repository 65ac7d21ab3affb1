#pragma once
// The phase function of a cloud of drops at one wavelength, averaged over their sizes:
//   P(θ) = 4π ∫ n(r) S11(θ, r) dr / (k² ∫ n(r) C_sca(r) dr),   S11 = (|S1|² + |S2|²)/2,
// k = 2π/λ, C_sca = πr² Qsca (Bohren & Huffman 1983, §3.4 and §4.4), normalised so that
// ∫ P dΩ / 4π = 1. Unpolarised light; the drops are in a non-absorbing medium.
#include "components/glory/mie/drop_size_distribution.h"
#include "components/glory/mie/mie_coefficients.h"

#include <vector>

namespace aurorawall::components::glory::mie {

struct PhaseFunction {
    std::vector<double> anglesRad;
    std::vector<double> value;         // P(θ)
    std::vector<double> errorEstimate; // the quadrature's estimate of |P − exact| (0 for a single size)
    double scatteringCrossSectionUm2 = 0.0; // ⟨C_sca⟩ = ∫ n C_sca dr / ∫ n dr
    int mieEvaluations = 0;                 // radii at which the Mie series was summed
};

// Over the radii of `drops` (DropSizeDistribution::radiusRangeUm), by globally adaptive Gauss–Kronrod
// 7/15 (Boost.Math's nodes and weights): the range starts as panels of at most 2 in size parameter (one
// ripple of the Mie resonances), then the panel with the largest Kronrod–Gauss difference at the angle
// (or in C_sca) furthest from its tolerance is halved, until at every angle and in C_sca the summed
// differences are at most `relativeTolerance` of the integral, or `maxPanels` is reached (then the error
// estimate says how far it got). The error estimate of P adds the relative estimates of numerator and
// denominator; the Kronrod–Gauss difference overestimates the error of the Kronrod result.
PhaseFunction sizeAveragedPhaseFunction(const DropSizeDistribution& drops, double wavelengthUm, RefractiveIndex index,
                                        const std::vector<double>& anglesRad, double relativeTolerance = 1e-6,
                                        int maxPanels = 20000);

} // namespace aurorawall::components::glory::mie
