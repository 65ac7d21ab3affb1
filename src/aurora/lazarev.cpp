#include "aurora/lazarev.h"

#include "aurora/atmosphere_profile.h"

#include <cmath>

namespace aurorawall::aurora {

double characteristicMass(double energyKeV)
{
    return 4.6e-6 * std::pow(energyKeV, 1.65);
}

double lazarevRate(double r)
{
    return 4.2 * r * std::exp(-r * r - r) + 0.48 * std::exp(-17.4 * std::pow(r, 1.37));
}

// ∫_0^∞ L dr by Simpson's rule: on [0, 1] in s with r = s⁴ (dr = 4s³ ds), which smooths the
// r^1.37 kink at 0 into s^5.48; on [1, 8] directly (L < 1e-29 beyond). 4000 intervals each.
double lazarevRateIntegral()
{
    auto simpson = [](auto f, double a, double b) {
        constexpr int kIntervals = 4000;
        double h = (b - a) / kIntervals;
        double sum = f(a) + f(b);
        for (int i = 1; i < kIntervals; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(a + i * h);
        return sum * h / 3.0;
    };
    auto inS = [](double s) { return lazarevRate(s * s * s * s) * 4.0 * s * s * s; };
    return simpson(inS, 0.0, 1.0) + simpson(lazarevRate, 1.0, 8.0);
}

namespace {

// A = L(M/M_E)·E·D/M_E for an atmosphere of density D and shielding mass M at the altitude.
double depositionPerElectronIn(double density, double shielding, double energyKeV)
{
    double massE = characteristicMass(energyKeV);
    return lazarevRate(shielding / massE) * energyKeV * density / massE;
}

} // namespace

double depositionPerElectron(double altitudeKm, double energyKeV)
{
    return depositionPerElectronIn(massDensity(altitudeKm), shieldingMass(altitudeKm), energyKeV);
}

double depositionPerEnergyFlux(double altitudeKm, double energyKeV, Spectrum spectrum)
{
    return depositionPerEnergyFlux(massDensity(altitudeKm), shieldingMass(altitudeKm), energyKeV, spectrum);
}

double depositionPerEnergyFlux(double density, double shielding, double energyKeV, Spectrum spectrum)
{
    if (spectrum == Spectrum::Monoenergetic)
        return depositionPerElectronIn(density, shielding, energyKeV) / energyKeV;
    // E = E0·x, u = ln x: ∫ φ A dE = E0² ∫ x² e^{−x} A(z, E0 x) du (φ = E e^{−E/E0}, dE = E du).
    const double e0 = energyKeV;
    const double u0 = std::log(0.01), u1 = std::log(30.0);
    constexpr int kIntervals = 256;
    const double h = (u1 - u0) / kIntervals;
    double sum = 0.0;
    for (int i = 0; i <= kIntervals; ++i) {
        double x = std::exp(u0 + i * h);
        double weight = (i == 0 || i == kIntervals) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        sum += weight * x * x * std::exp(-x) * depositionPerElectronIn(density, shielding, e0 * x);
    }
    double numerator = e0 * e0 * sum * h / 3.0;
    return numerator / (2.0 * e0 * e0 * e0);
}

} // namespace aurorawall::aurora
