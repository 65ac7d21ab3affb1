#include "components/aurora/physics/lazarev.h"

#include "components/aurora/physics/atmosphere_profile.h"

#include <boost/math/quadrature/exp_sinh.hpp>

#include <cmath>

namespace aurorawall::components::aurora::physics {

double characteristicMass(double energyKeV)
{
    return 4.6e-6 * std::pow(energyKeV, 1.65);
}

double lazarevRate(double r)
{
    // From r = 28 on both terms underflow to exactly 0 (e^{−812}, e^{−1672} < 4.9e-324): skip them.
    if (r >= 28.0)
        return 0.0;
    return 4.2 * r * std::exp(-r * r - r) + 0.48 * std::exp(-17.4 * std::pow(r, 1.37));
}

// ∫_0^∞ L dr by the exp-sinh rule (Boost.Math; Tanaka et al. 2009), made for [0, ∞): its nodes
// crowd towards r = 0, where the r^1.37 term has an unbounded second derivative, and thin out
// into the e^{−r²} tail. Matches the closed form
//   4.2·(½ − (√π/4)·e^{1/4}·erfc(½)) + 0.48·Γ(1 + 1/1.37)/17.4^{1/1.37}
// to rounding (tested; docs/ACCURACY.md, "Quadratures").
double lazarevRateIntegral()
{
    static const double integral = boost::math::quadrature::exp_sinh<double>().integrate(lazarevRate, 1e-14);
    return integral;
}

double monoenergeticDepositionPerEnergyFlux(double density, double shielding, double characteristicMassGPerCm2)
{
    return lazarevRate(shielding / characteristicMassGPerCm2) * density / characteristicMassGPerCm2;
}

namespace {

// A = L(M/M_E)·E·D/M_E for an atmosphere of density D and shielding mass M at the altitude.
double depositionPerElectronIn(double density, double shielding, double energyKeV)
{
    return monoenergeticDepositionPerEnergyFlux(density, shielding, characteristicMass(energyKeV)) * energyKeV;
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
        return monoenergeticDepositionPerEnergyFlux(density, shielding, characteristicMass(energyKeV));
    // E = E0·x, u = ln x: ∫ φ A dE = E0² ∫ x² e^{−x} A(z, E0 x) du (φ = E e^{−E/E0}, dE = E du).
    // A fixed Simpson rule, not an adaptive one: the table builder calls this for every altitude
    // and energy, and 257 samples of a smooth integrand in ln E cost the same everywhere; within
    // 3e-10 of adaptive Gauss–Kronrod wherever the deposition exceeds 1e-3 of its peak
    // (docs/ACCURACY.md, "Quadratures").
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

} // namespace aurorawall::components::aurora::physics
