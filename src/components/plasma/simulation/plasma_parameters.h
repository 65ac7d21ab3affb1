#pragma once
// Physical constants (SI, CODATA 2018) and the plasma's characteristic scales.
#include <cmath>

namespace aurorawall::plasma {

inline constexpr double kElementaryCharge = 1.602176634e-19;  // C (exact)
inline constexpr double kElectronMass = 9.1093837015e-31;     // kg
inline constexpr double kVacuumPermittivity = 8.8541878128e-12; // F/m

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

} // namespace aurorawall::plasma
