#pragma once
// The neutral atmosphere the aurora is deposited in: US Standard Atmosphere 1976 (USSA76,
// NOAA-S/T 76-1562). See docs/aurora-physics.md, "Atmosphere".
// Altitudes are geometric, in km; densities in cgs (g/cm³, g/cm², cm⁻³).

namespace aurorawall::components::aurora::physics {

// Mass density D(z), g/cm³: US Standard Atmosphere 1976 values (75–1000 km, plus 50/60/70 km),
// interpolated log-linearly, i.e. exponential between table altitudes; below the first and above
// the last altitude the nearest segment's exponential continues.
double massDensity(double altitudeKm);

// Shielding mass M(z) = ∫_z^∞ D(z') dz', g/cm², in closed form: on a segment with scale height
// H = Δz / ln(D_i / D_{i+1}) the integral of D_i e^{−(z−z_i)/H} is H (D(z) − D_{i+1}); the tail above
// the last altitude is D_last·H_last.
double shieldingMass(double altitudeKm);

// USSA76 kinetic temperature, K, from its defining layers: geopotential lapse rates below 86 km,
// 186.8673 K for 86–91 km, the elliptical segment 91–110 km, +12 K/km for 110–120 km and
// T = 1000 − 640·exp(−0.01875·ξ), ξ = (z − 120)(R + 120)/(R + z), R = 6356.766 km, above.
double temperatureK(double altitudeKm);

// Number densities, cm⁻³, of the three gases that matter for the aurora.
struct NumberDensities {
    double n2 = 0.0;
    double o2 = 0.0;
    double o = 0.0;
    double total() const { return n2 + o2 + o; }
};

// Simplified composition: a mole fraction x_O(z) of atomic oxygen (docs/aurora-physics.md) and the
// rest molecular air with N2 : O2 = 0.79 : 0.21 (argon counted as N2); n = D / (m̄ u) with
// m̄ = 15.999·x_O + 28.964·(1 − x_O).
double atomicOxygenFraction(double altitudeKm);
NumberDensities numberDensities(double altitudeKm);

} // namespace aurorawall::components::aurora::physics
