#include "components/glory/mie/phase_function.h"

#include "physics/constants.h"
#include "components/glory/mie/mie_scattering.h"

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace aurorawall::components::glory::mie {
namespace {

// The integrand at one radius: n(r)·S11(θⱼ, r) for each angle, then n(r)·C_sca(r) (µm²).
struct Integrand {
    const DropSizeDistribution& drops;
    double wavenumber; // k = 2π/λ, µm⁻¹
    RefractiveIndex index;
    std::vector<double> cosines;
    int* evaluations;

    std::vector<double> operator()(double radiusUm) const
    {
        ++*evaluations;
        const MieCoefficients c = mieCoefficients(wavenumber * radiusUm, index);
        const double density = std::exp(drops.logDensity(radiusUm));
        std::vector<double> values(cosines.size() + 1);
        for (size_t j = 0; j < cosines.size(); ++j) {
            const Amplitudes s = amplitudesAtCosine(c, cosines[j]);
            values[j] = density * 0.5 * (std::norm(s.s1) + std::norm(s.s2));
        }
        values.back() = density * physics::kPi * radiusUm * radiusUm * efficiencies(c).scattering;
        return values;
    }
};

struct Panel {
    double a, b;
    std::vector<double> kronrod, difference; // the 15-point result and |Kronrod − Gauss| per component
};

// Gauss–Kronrod 7/15 on [a, b]: the Gauss nodes are every other Kronrod node, starting at the centre.
Panel integratePanel(const Integrand& f, double a, double b, double densityNormalisation)
{
    using Kronrod = boost::math::quadrature::gauss_kronrod<double, 15>;
    using Gauss = boost::math::quadrature::gauss<double, 7>;
    const auto& nodes = Kronrod::abscissa();
    const auto& kronrodWeights = Kronrod::weights();
    const auto& gaussWeights = Gauss::weights();
    const double centre = 0.5 * (a + b), halfWidth = 0.5 * (b - a);
    Panel panel{a, b, {}, {}};
    std::vector<double> gauss;
    for (size_t i = 0; i < nodes.size(); ++i) {
        std::vector<double> sum = f(centre + halfWidth * nodes[i]);
        if (i > 0) {
            const std::vector<double> mirrored = f(centre - halfWidth * nodes[i]);
            for (size_t j = 0; j < sum.size(); ++j) sum[j] += mirrored[j];
        }
        if (panel.kronrod.empty()) {
            panel.kronrod.assign(sum.size(), 0.0);
            gauss.assign(sum.size(), 0.0);
        }
        for (size_t j = 0; j < sum.size(); ++j) {
            const double value = sum[j] * densityNormalisation;
            panel.kronrod[j] += kronrodWeights[i] * value;
            if (i % 2 == 0) gauss[j] += gaussWeights[i / 2] * value;
        }
    }
    panel.difference.resize(gauss.size());
    for (size_t j = 0; j < gauss.size(); ++j) {
        panel.kronrod[j] *= halfWidth;
        panel.difference[j] = std::abs(panel.kronrod[j] - halfWidth * gauss[j]);
    }
    return panel;
}

PhaseFunction singleSizePhaseFunction(double x, double radiusUm, RefractiveIndex index,
                                      const std::vector<double>& anglesRad)
{
    const MieCoefficients c = mieCoefficients(x, index);
    const double qsca = efficiencies(c).scattering;
    PhaseFunction p;
    p.anglesRad = anglesRad;
    p.errorEstimate.assign(anglesRad.size(), 0.0);
    p.scatteringCrossSectionUm2 = physics::kPi * radiusUm * radiusUm * qsca;
    p.mieEvaluations = 1;
    // 4π S11/(k² πr² Qsca) = 4 S11/(x² Qsca).
    for (double theta : anglesRad) {
        const Amplitudes s = amplitudesAtCosine(c, std::cos(theta));
        p.value.push_back(2.0 * (std::norm(s.s1) + std::norm(s.s2)) / (x * x * qsca));
    }
    return p;
}

} // namespace

PhaseFunction sizeAveragedPhaseFunction(const DropSizeDistribution& drops, double wavelengthUm, RefractiveIndex index,
                                        const std::vector<double>& anglesRad, double relativeTolerance, int maxPanels)
{
    if (!(wavelengthUm > 0.0)) throw std::invalid_argument("wavelength must be > 0");
    const double wavenumber = 2.0 * physics::kPi / wavelengthUm;
    if (drops.isSingleSize())
        return singleSizePhaseFunction(wavenumber * drops.effectiveRadiusUm(), drops.effectiveRadiusUm(), index,
                                       anglesRad);

    PhaseFunction p;
    p.anglesRad = anglesRad;
    Integrand f{drops, wavenumber, index, {}, &p.mieEvaluations};
    for (double theta : anglesRad) f.cosines.push_back(std::cos(theta));

    // ∫ n dr by the same rule (n is smooth), for ⟨C_sca⟩ only: P does not depend on n's scale.
    const auto [rMin, rMax] = drops.radiusRangeUm();
    const double numberOfDrops = boost::math::quadrature::gauss_kronrod<double, 15>::integrate(
        [&](double r) { return std::exp(drops.logDensity(r)); }, rMin, rMax, 15, 1e-12);

    constexpr double kMaxPanelWidthInX = 2.0;
    const int initialPanels = std::max(1, int(std::ceil(wavenumber * (rMax - rMin) / kMaxPanelWidthInX)));
    std::vector<Panel> panels;
    for (int i = 0; i < initialPanels; ++i) {
        const double a = rMin + (rMax - rMin) * i / initialPanels;
        const double b = i + 1 == initialPanels ? rMax : rMin + (rMax - rMin) * (i + 1) / initialPanels;
        panels.push_back(integratePanel(f, a, b, 1.0 / numberOfDrops));
    }
    const size_t components = anglesRad.size() + 1;
    std::vector<double> total(components, 0.0), error(components, 0.0);
    const auto account = [&](const Panel& panel, double sign) {
        for (size_t j = 0; j < components; ++j) {
            total[j] += sign * panel.kronrod[j];
            error[j] += sign * panel.difference[j];
        }
    };
    for (const Panel& panel : panels) account(panel, 1.0);
    for (;;) {
        size_t worst = 0;
        for (size_t j = 1; j < components; ++j)
            if (error[j] * std::abs(total[worst]) > error[worst] * std::abs(total[j])) worst = j;
        if (error[worst] <= relativeTolerance * std::abs(total[worst]) || int(panels.size()) >= maxPanels) break;
        const auto largest = std::max_element(panels.begin(), panels.end(), [&](const Panel& l, const Panel& r) {
            return l.difference[worst] < r.difference[worst];
        });
        const double a = largest->a, b = largest->b, middle = 0.5 * (a + b);
        account(*largest, -1.0);
        *largest = integratePanel(f, a, middle, 1.0 / numberOfDrops);
        account(*largest, 1.0);
        panels.push_back(integratePanel(f, middle, b, 1.0 / numberOfDrops));
        account(panels.back(), 1.0);
    }
    // The running sums drift by rounding; sum once more.
    std::fill(total.begin(), total.end(), 0.0);
    std::fill(error.begin(), error.end(), 0.0);
    for (const Panel& panel : panels) account(panel, 1.0);

    const double crossSection = total.back();
    const double crossSectionRelativeError = error.back() / crossSection;
    p.scatteringCrossSectionUm2 = crossSection;
    for (size_t j = 0; j < anglesRad.size(); ++j) {
        const double value = 4.0 * physics::kPi * total[j] / (wavenumber * wavenumber * crossSection);
        p.value.push_back(value);
        p.errorEstimate.push_back(value * (error[j] / total[j] + crossSectionRelativeError));
    }
    return p;
}

} // namespace aurorawall::components::glory::mie
