#pragma once
// Auroral emissions: altitude-dependent yields (photons per keV deposited) of the four emissions the
// renderer draws, and their volume and column rates. See docs/aurora-physics.md, "Emission".
#include "components/aurora/physics/lazarev.h"
#include "physics/emission_lines.h"

#include <glm/glm.hpp>

namespace aurorawall::components::aurora::physics {

// The lines themselves are shared physics (src/physics/emission_lines.h).
using aurorawall::physics::EmissionLine;
using aurorawall::physics::kLineCount;
using aurorawall::physics::LineInfo;
using aurorawall::physics::lineInfo;

// Fraction of N2(A) excitation energy transferred to O (producing O(1S)) rather than lost to O2:
// f = k_O n_O / (k_O n_O + k_O2 n_O2), k_O = 2.8e-11, k_O2 = 2.5e-12 cm³/s (Piper et al. 1981).
double oxygenTransferFraction(double altitudeKm);

// Fraction of O(1S) atoms that radiate: A / (A + k n_O2), A = 1.35 s⁻¹,
// k = 4.0e-12·exp(−865/T) cm³/s (Slanger, Wood & Black 1972).
double o1sRadiatingFraction(double altitudeKm);

// Fraction of O(1D) atoms that radiate: A / (A + k_N2 n_N2 + k_O2 n_O2), A = 7.45e-3 s⁻¹,
// k_N2 = 2.0e-11·exp(107.8/T), k_O2 = 2.9e-11·exp(67.5/T) cm³/s (Streit et al. 1976).
double o1dRadiatingFraction(double altitudeKm);

// Photons of the line emitted per keV deposited at altitude z (docs/aurora-physics.md):
//   427.8: 0.4213·(1 − x_O);  N2 1PG: 0.4213·(1 − x_O);
//   557.7: 2.213·(1 − x_O)·f_transfer·q_1S;  630.0: 8·x_O·q_1D·0.756.
double lineYield(EmissionLine line, double altitudeKm);

// Volume emission rate, photons cm⁻³ s⁻¹ per erg cm⁻² s⁻¹ of incident energy flux:
// depositionPerEnergyFlux · kKeVPerErg · lineYield.
double volumeEmissionRate(EmissionLine line, double altitudeKm, double energyKeV, Spectrum spectrum);

// Vertical column brightness, rayleigh per erg cm⁻² s⁻¹: ∫ volume rate dz (cm) / 1e6, 60–1000 km.
double columnBrightnessRayleigh(EmissionLine line, double energyKeV, Spectrum spectrum);

} // namespace aurorawall::components::aurora::physics
