#pragma once
// Lazarev energy deposition of auroral electrons (Lawlor & Genetti §2.1, after Lummerzheim 1992), over the
// USSA76 profile of aurora/atmosphere_profile.h. See docs/aurora-physics.md, "Deposition".
#include "physics/constants.h"

namespace aurorawall::components::aurora::physics {

using aurorawall::physics::kKeVPerErg; // the deposition's energy flux, erg cm⁻² s⁻¹, in keV

// Characteristic shielding mass M_E = 4.6e-6 · E^1.65 g/cm², E in keV.
double characteristicMass(double energyKeV);

// Lazarev's unscaled interaction rate L(r) = 4.2 r e^{−r²−r} + 0.48 e^{−17.4 r^1.37}, r = M/M_E.
double lazarevRate(double r);

// ∫_0^∞ L(r) dr: the fraction of the incident energy the atmosphere absorbs (≈ 1.0).
double lazarevRateIntegral();

// A(z) = L(r) · E · D(z) / M_E, r = M(z)/M_E: energy deposited per cm of altitude per incident
// electron of energy E, keV/cm (equivalently keV cm⁻³ s⁻¹ per electron cm⁻² s⁻¹).
double depositionPerElectron(double altitudeKm, double energyKeV);

enum class Spectrum {
    Monoenergetic, // all electrons at E
    Maxwellian,    // number flux φ(E) ∝ E e^{−E/E0}, characteristic energy E0, mean energy 2·E0
};

// Energy deposited per cm of altitude per unit incident energy flux, cm⁻¹
// (keV cm⁻³ s⁻¹ per keV cm⁻² s⁻¹). Monoenergetic: A(z, E)/E. Maxwellian with E0 = energyKeV:
// ∫ φ(E) A(z, E) dE / ∫ φ(E) E dE, the denominator exactly 2 E0³ (total energy flux fixed), the
// numerator by Simpson's rule in ln E over [0.01, 30]·E0 (the energy outside holds < 1e-6 of the flux).
double depositionPerEnergyFlux(double altitudeKm, double energyKeV, Spectrum spectrum);

// The same at an altitude whose mass density D (g/cm^3) and shielding mass M (g/cm^2) are
// already known: the table builder evaluates the atmosphere once per altitude for all energies.
double depositionPerEnergyFlux(double densityGPerCm3, double shieldingMassGPerCm2, double energyKeV,
                               Spectrum spectrum);

// The monoenergetic A/E = L(M/M_E)·D/M_E, cm⁻¹, for an energy whose characteristic mass M_E (g/cm²)
// is already known: the Maxwellian table evaluates M_E once per energy for all altitudes.
double monoenergeticDepositionPerEnergyFlux(double densityGPerCm3, double shieldingMassGPerCm2,
                                            double characteristicMassGPerCm2);

} // namespace aurorawall::components::aurora::physics
