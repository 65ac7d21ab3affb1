#pragma once
// Physical constants (SI, CODATA 2018; defined in src/physics/constants.h) and the plasma's characteristic scales.
#include "physics/constants.h"

#include <cmath>

namespace aurorawall::components::plasma::simulation {

using physics::kElementaryCharge;   // C (exact)
using physics::kElectronMass;       // kg
using physics::kVacuumPermittivity; // F/m

// Electron plasma frequency ω_p = √(n e²/(ε₀ mₑ)) (rad/s) of an electron density n (m⁻³):
// 56.41 √n rad/s.
inline double plasmaFrequency(double electronDensity)
{
    return std::sqrt(electronDensity * kElementaryCharge * kElementaryCharge / (kVacuumPermittivity * kElectronMass));
}

// Electron cyclotron frequency ω_c = e B/mₑ (rad/s) in a field of B tesla.
inline double cyclotronFrequency(double magneticFieldTesla)
{
    return kElementaryCharge * magneticFieldTesla / kElectronMass;
}

// Debye length λ_D = v_th/ω_p (m), v_th = √(k T/mₑ) the thermal speed (m/s) of one velocity component.
inline double debyeLength(double thermalSpeed, double electronDensity)
{
    return thermalSpeed / plasmaFrequency(electronDensity);
}

} // namespace aurorawall::components::plasma::simulation
