#include "components/aurora/physics/emission.h"

#include "components/aurora/physics/atmosphere_profile.h"

#include <cmath>

namespace aurorawall::components::aurora::physics {
namespace {

// 427.8 nm photons per keV deposited in the molecular share, calibrated so that a 5 keV beam gives
// the classic 213 R per erg cm⁻² s⁻¹ (Rees & Luckey 1974): 0.341 photons/keV over the whole column.
constexpr double kBluePhotonsPerKeV = 0.4213;
// Visible N2 1PG photons per 427.8 photon: assumed 1 (order of magnitude, Vallance Jones 1974).
constexpr double kFirstPositivePerBlue = 1.0;
// 557.7 nm photons per keV deposited in the molecular share with full transfer and no quenching:
// calibrated so that a 5 keV beam gives the commonly quoted 1 kR per erg cm⁻² s⁻¹ (Omholt 1971).
constexpr double kGreenPhotonsPerKeV = 2.213;
// O(1D) atoms per keV deposited in the atomic-oxygen share: calibrated so that 630.0 nm outshines
// 557.7 nm (linear sRGB red > green) above ≈ 220 km, as photographs show (red 630.0 nm dominates above ~200 km).
constexpr double kO1DPerKeV = 8.0;
constexpr double kRedBranching = 5.63e-3 / 7.45e-3; // A(630.0)/A(1D) (NIST ASD)

} // namespace

double oxygenTransferFraction(double altitudeKm)
{
    NumberDensities n = numberDensities(altitudeKm);
    double toOxygen = 2.8e-11 * n.o;
    return toOxygen / (toOxygen + 2.5e-12 * n.o2);
}

double o1sRadiatingFraction(double altitudeKm)
{
    constexpr double kEinsteinA = 1.35;
    double quenching = 4.0e-12 * std::exp(-865.0 / temperatureK(altitudeKm)) * numberDensities(altitudeKm).o2;
    return kEinsteinA / (kEinsteinA + quenching);
}

double o1dRadiatingFraction(double altitudeKm)
{
    constexpr double kEinsteinA = 7.45e-3;
    double t = temperatureK(altitudeKm);
    NumberDensities n = numberDensities(altitudeKm);
    double quenching = 2.0e-11 * std::exp(107.8 / t) * n.n2 + 2.9e-11 * std::exp(67.5 / t) * n.o2;
    return kEinsteinA / (kEinsteinA + quenching);
}

double lineYield(EmissionLine line, double altitudeKm)
{
    double molecular = 1.0 - atomicOxygenFraction(altitudeKm);
    switch (line) {
    case EmissionLine::Blue4278: return kBluePhotonsPerKeV * molecular;
    case EmissionLine::N2FirstPositive: return kFirstPositivePerBlue * kBluePhotonsPerKeV * molecular;
    case EmissionLine::Green5577:
        return kGreenPhotonsPerKeV * molecular * oxygenTransferFraction(altitudeKm) * o1sRadiatingFraction(altitudeKm);
    case EmissionLine::Red6300:
        return kO1DPerKeV * atomicOxygenFraction(altitudeKm) * o1dRadiatingFraction(altitudeKm) * kRedBranching;
    }
    return 0.0;
}

double volumeEmissionRate(EmissionLine line, double altitudeKm, double energyKeV, Spectrum spectrum)
{
    return depositionPerEnergyFlux(altitudeKm, energyKeV, spectrum) * kKeVPerErg * lineYield(line, altitudeKm);
}

// Simpson's rule over 60–1000 km in 0.1 km steps (the profiles vary on scales ≥ 1 km). Kept
// against adaptive Gauss–Kronrod (Boost.Math, 10/21 to 1e-10): that was 1.5–5.7 times faster but
// less accurate, 4e-9 to 7e-8 against the closed-form deposition column where Simpson gives
// 9e-12 to 3e-10 (docs/ACCURACY.md, "Quadratures").
double columnBrightnessRayleigh(EmissionLine line, double energyKeV, Spectrum spectrum)
{
    constexpr double kBottomKm = 60.0, kTopKm = 1000.0;
    constexpr int kIntervals = 9400;
    const double h = (kTopKm - kBottomKm) / kIntervals;
    double sum = 0.0;
    for (int i = 0; i <= kIntervals; ++i) {
        double weight = (i == 0 || i == kIntervals) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        sum += weight * volumeEmissionRate(line, kBottomKm + i * h, energyKeV, spectrum);
    }
    return sum * h / 3.0 * 1e5 / 1e6;
}

} // namespace aurorawall::components::aurora::physics
