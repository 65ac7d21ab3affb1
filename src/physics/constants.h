#pragma once
// The constants of the C++ code, each defined once (GLSL has its own, once, in
// shaders/physics/constants.glsl); tests/physics/constants_test.cpp scans the sources for copies.
namespace aurorawall::physics {

// Mathematical.
inline constexpr double kPi = 3.14159265358979323846264338327950288;
inline constexpr double kDegree = kPi / 180.0; // radians per degree

// Physical (SI; the 2019 SI's exact values, CODATA 2018 for the measured ones).
inline constexpr double kPlanck = 6.62607015e-34;              // h, J s (exact)
inline constexpr double kSpeedOfLight = 2.99792458e8;          // c, m/s (exact)
inline constexpr double kBoltzmann = 1.380649e-23;             // k, J/K (exact)
inline constexpr double kElementaryCharge = 1.602176634e-19;   // e, C (exact)
inline constexpr double kElectronMass = 9.1093837015e-31;      // mₑ, kg
inline constexpr double kVacuumPermittivity = 8.8541878128e-12; // ε₀, F/m

// Energy units derived from them: 1 keV = 1e3 e J and 1 erg = 1e-7 J, so 1 keV = 1e10 e erg (1e-10/e
// rounds to the nearest double of the exact ratio).
inline constexpr double kKeVPerErg = 1e-10 / kElementaryCharge; // keV per erg

// Photometric: the luminous efficacy of monochromatic light at 540 THz (≈ 555 nm), lm/W (exact), so
// Y = 683 ∫ L_λ ȳ dλ is in cd/m² for a spectral radiance L_λ in W m⁻² sr⁻¹ nm⁻¹ (CIE photopic).
inline constexpr double kLumensPerWatt = 683.0;

} // namespace aurorawall::physics
