#include "components/aurora/physics/atmosphere_profile.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace aurorawall::components::aurora::physics {
namespace {

constexpr double kCmPerKm = 1e5;
constexpr double kAtomicMassUnitG = 1.66053906660e-24;   // CODATA 2018
constexpr double kMolecularAirMass = 28.9644;            // USSA76 sea-level mean molecular weight
constexpr double kAtomicOxygenMass = 15.9994;

struct TablePoint {
    double altitudeKm;
    double value;
};

// US Standard Atmosphere 1976 (USSA76) mass density, kg/m³, its published values at 50–1000 km.
constexpr std::array<TablePoint, 17> kDensityKgM3{{
    {50, 1.0269e-3}, {60, 3.0968e-4}, {70, 8.2829e-5}, {75, 3.9921e-5}, {85, 8.2196e-6},
    {100, 5.604e-7}, {115, 4.289e-8}, {130, 8.152e-9}, {150, 2.076e-9}, {175, 6.339e-10},
    {200, 2.541e-10}, {250, 6.073e-11}, {300, 1.916e-11}, {400, 2.803e-12}, {500, 5.215e-13},
    {750, 1.788e-14}, {1000, 3.561e-15}}};

// Atomic-oxygen mole fraction. 86 and 100 km: USSA76 number densities (N2, O2, O, Ar:
// 1.130e20, 3.031e19, 8.6e16, 1.351e18 m⁻³ at 86 km; 9.210e18, 2.151e18, 4.298e17, 9.4e16 at 100 km,
// which reproduce the table densities 6.958e-6 and 5.604e-7 kg/m³). Above: from the USSA76 mean
// molecular weight m̄ with two gases, x_O = (28.964 − m̄)/(28.964 − 15.999), capped at 1
// (m̄ = 27.27, 26.20, 24.10, 21.30, 17.73 at 110, 120, 150, 200, 300 km; ≈ 16 at 400 km).
constexpr std::array<TablePoint, 8> kAtomicOxygenFraction{{
    {86, 5.94e-4}, {100, 3.62e-2}, {110, 0.131}, {120, 0.213}, {150, 0.375}, {200, 0.591},
    {300, 0.866}, {400, 1.0}}};

// Index i of the segment [z_i, z_{i+1}] holding z; the end segments extend outward.
template <std::size_t N>
std::size_t segmentOf(const std::array<TablePoint, N>& table, double altitudeKm)
{
    std::size_t i = 0;
    while (i + 2 < N && altitudeKm > table[i + 1].altitudeKm) ++i;
    return i;
}

// Log-linear interpolation: v(z) = v_i (v_{i+1}/v_i)^{(z − z_i)/(z_{i+1} − z_i)}.
template <std::size_t N>
double logLinear(const std::array<TablePoint, N>& table, double altitudeKm)
{
    std::size_t i = segmentOf(table, altitudeKm);
    const TablePoint& a = table[i];
    const TablePoint& b = table[i + 1];
    double t = (altitudeKm - a.altitudeKm) / (b.altitudeKm - a.altitudeKm);
    return a.value * std::pow(b.value / a.value, t);
}

// Scale height of segment i, cm: H = (z_{i+1} − z_i) / ln(D_i / D_{i+1}).
double scaleHeightCm(std::size_t i)
{
    return (kDensityKgM3[i + 1].altitudeKm - kDensityKgM3[i].altitudeKm) * kCmPerKm /
           std::log(kDensityKgM3[i].value / kDensityKgM3[i + 1].value);
}

// Shielding mass above each table altitude, g/cm²: M(z_i) = Σ_{j≥i} H_j (D_j − D_{j+1}) + D_last H_last.
std::vector<double> shieldingMassAtTableAltitudes()
{
    constexpr double kGramPerCm3PerKgPerM3 = 1e-3;
    const std::size_t n = kDensityKgM3.size();
    std::vector<double> mass(n);
    mass[n - 1] = kDensityKgM3[n - 1].value * kGramPerCm3PerKgPerM3 * scaleHeightCm(n - 2);
    for (std::size_t i = n - 1; i-- > 0;) {
        mass[i] = mass[i + 1] + scaleHeightCm(i) * (kDensityKgM3[i].value - kDensityKgM3[i + 1].value) *
                                    kGramPerCm3PerKgPerM3;
    }
    return mass;
}

} // namespace

double massDensity(double altitudeKm)
{
    return 1e-3 * logLinear(kDensityKgM3, altitudeKm);
}

double shieldingMass(double altitudeKm)
{
    static const std::vector<double> tableMass = shieldingMassAtTableAltitudes();
    const std::size_t last = kDensityKgM3.size() - 1;
    if (altitudeKm >= kDensityKgM3[last].altitudeKm) {
        return massDensity(altitudeKm) * scaleHeightCm(last - 1);
    }
    std::size_t i = segmentOf(kDensityKgM3, altitudeKm);
    double top = kDensityKgM3[i + 1].value * 1e-3;
    return tableMass[i + 1] + scaleHeightCm(i) * (massDensity(altitudeKm) - top);
}

double temperatureK(double altitudeKm)
{
    constexpr double kEarthRadiusKm = 6356.766; // USSA76 r0
    if (altitudeKm < 86.0) {
        // Molecular-scale temperature of the geopotential layers 47–84.852 km' (within 0.1 K of the
        // kinetic temperature there).
        double geopotentialKm = kEarthRadiusKm * altitudeKm / (kEarthRadiusKm + altitudeKm);
        if (geopotentialKm < 51.0) return 270.65;
        if (geopotentialKm < 71.0) return 270.65 - 2.8 * (geopotentialKm - 51.0);
        return 214.65 - 2.0 * (geopotentialKm - 71.0);
    }
    if (altitudeKm < 91.0) return 186.8673;
    if (altitudeKm < 110.0) {
        double s = (altitudeKm - 91.0) / -19.9429;
        return 263.1905 - 76.3232 * std::sqrt(1.0 - s * s);
    }
    if (altitudeKm < 120.0) return 240.0 + 12.0 * (altitudeKm - 110.0);
    double xi = (altitudeKm - 120.0) * (kEarthRadiusKm + 120.0) / (kEarthRadiusKm + altitudeKm);
    return 1000.0 - 640.0 * std::exp(-0.01875 * xi);
}

double atomicOxygenFraction(double altitudeKm)
{
    return std::min(1.0, logLinear(kAtomicOxygenFraction, altitudeKm));
}

NumberDensities numberDensities(double altitudeKm)
{
    double xO = atomicOxygenFraction(altitudeKm);
    double meanMass = kAtomicOxygenMass * xO + kMolecularAirMass * (1.0 - xO);
    double total = massDensity(altitudeKm) / (meanMass * kAtomicMassUnitG);
    return {0.79 * (1.0 - xO) * total, 0.21 * (1.0 - xO) * total, xO * total};
}

} // namespace aurorawall::components::aurora::physics
