#include "physics/constants.h"
#include "components/glory/optics/glory_table.h"

#include "common/glsl.h"
#include "physics/colour.h"
#include "components/glory/mie/mie_coefficients.h"
#include "components/glory/mie/mie_scattering.h"
#include "physics/colour_matching.h"
#include "components/glory/optics/water.h"

#include <boost/math/quadrature/gauss.hpp>

#include <algorithm>
#include <cmath>
#include <thread>

namespace aurorawall::components::glory::optics {

namespace {


namespace f64 {
AURORAWALL_GLSL_PRECISION(double)
#include "components/glory/glory_angle.glsl"
} // namespace f64

// πₙ(μ), τₙ(μ) for n = 1 … terms at each grid angle, stored [n−1][angle] so that the sums over the
// angles of one n run over contiguous memory (Bohren & Huffman 1983, eq. 4.47).
struct AngularFunctions {
    int angles = 0;
    int terms = 0;
    std::vector<double> pi, tau;

    AngularFunctions(const AngleGrid& grid, int termCount) : angles(grid.size()), terms(termCount)
    {
        pi.assign(size_t(terms) * size_t(angles), 0.0);
        tau.assign(pi.size(), 0.0);
        for (int a = 0; a < angles; ++a) {
            const double mu = -std::cos(grid.angle(a)); // cos θ, θ = π − γ
            double previous = 0.0, current = 1.0;      // π₀, π₁
            for (int n = 1; n <= terms; ++n) {
                pi[size_t(n - 1) * size_t(angles) + size_t(a)] = current;
                tau[size_t(n - 1) * size_t(angles) + size_t(a)] = n * mu * current - (n + 1) * previous;
                const double next = ((2 * n + 1) * mu * current - (n + 1) * previous) / n;
                previous = current;
                current = next;
            }
        }
    }
};

// Adds weight·S11(θ) of one drop to `s11` at every grid angle; returns its Qsca.
double addDrop(double x, double n, const AngularFunctions& f, double weight, std::vector<double>& s11,
               std::vector<double>& work)
{
    const mie::MieCoefficients c = mie::mieCoefficients(x, {n, 0.0});
    const int terms = static_cast<int>(c.a.size());
    const size_t angles = size_t(f.angles);
    work.assign(4 * angles, 0.0); // Re S1, Im S1, Re S2, Im S2
    double* s1r = work.data();
    double* s1i = s1r + angles;
    double* s2r = s1i + angles;
    double* s2i = s2r + angles;
    for (int k = 1; k <= terms; ++k) {
        const double scale = (2.0 * k + 1.0) / (double(k) * (k + 1.0));
        const double ar = scale * c.a[k - 1].real(), ai = scale * c.a[k - 1].imag();
        const double br = scale * c.b[k - 1].real(), bi = scale * c.b[k - 1].imag();
        const double* p = f.pi.data() + size_t(k - 1) * angles;
        const double* t = f.tau.data() + size_t(k - 1) * angles;
        for (size_t a = 0; a < angles; ++a) {
            s1r[a] += ar * p[a] + br * t[a];
            s1i[a] += ai * p[a] + bi * t[a];
            s2r[a] += ar * t[a] + br * p[a];
            s2i[a] += ai * t[a] + bi * p[a];
        }
    }
    for (size_t a = 0; a < angles; ++a)
        s11[a] += weight * 0.5 * (s1r[a] * s1r[a] + s1i[a] * s1i[a] + s2r[a] * s2r[a] + s2i[a] * s2i[a]);
    return mie::efficiencies(c).scattering;
}

// The trapezoid rule's intervals over the radii [lo, hi] µm at wavenumber k (µm⁻¹): steps of at most
// sizeParameterStep in x = kr.
int radiusIntervals(double k, double lo, double hi, double sizeParameterStep)
{
    return std::max(2, static_cast<int>(std::ceil(k * (hi - lo) / sizeParameterStep)));
}

// One wavelength's row of the phase table; returns the number of Mie series summed.
long long phaseRow(const mie::DropSizeDistribution& drops, double wavelengthNm, const AngularFunctions& f,
                   double sizeParameterStep, double* row)
{
    const double k = 2.0 * physics::kPi / (wavelengthNm * 1e-3); // µm⁻¹
    const double n = waterRefractiveIndex(wavelengthNm);
    std::vector<double> s11(size_t(f.angles), 0.0), work;
    if (drops.isSingleSize()) {
        const double x = k * drops.effectiveRadiusUm();
        const double qsca = addDrop(x, n, f, 1.0, s11, work);
        for (int a = 0; a < f.angles; ++a)
            row[a] = 4.0 * s11[size_t(a)] / (x * x * qsca); // 4π S11 / (k² π r² Qsca)
        return 1;
    }
    const auto [lo, hi] = drops.radiusRangeUm();
    const int intervals = radiusIntervals(k, lo, hi, sizeParameterStep);
    const double dr = (hi - lo) / intervals;
    const double logMode = drops.logDensity(drops.effectiveRadiusUm());
    double crossSection = 0.0; // ∫ n C_sca dr, C_sca = π r² Qsca
    for (int j = 0; j <= intervals; ++j) {
        const double r = lo + j * dr;
        const double weight = ((j == 0 || j == intervals) ? 0.5 : 1.0) * std::exp(drops.logDensity(r) - logMode);
        if (weight == 0.0)
            continue;
        const double qsca = addDrop(k * r, n, f, weight, s11, work);
        crossSection += weight * physics::kPi * r * r * qsca;
    }
    for (int a = 0; a < f.angles; ++a)
        row[a] = 4.0 * physics::kPi * s11[size_t(a)] / (k * k * crossSection);
    return intervals + 1;
}

} // namespace

double AngleGrid::angle(int i) const
{
    const double middleSpan = physics::kPi - glorySpanRad - forwardSpanRad;
    if (i < gloryCount)
        return glorySpanRad * i / (gloryCount - 1);
    if (i < gloryCount + middleCount)
        return glorySpanRad + middleSpan * (i - gloryCount + 1) / middleCount;
    return glorySpanRad + middleSpan + forwardSpanRad * (i - gloryCount - middleCount + 1) / forwardCount;
}

double AngleGrid::index(double gammaRad) const
{
    return f64::gloryAngleIndex(gammaRad, {glorySpanRad, physics::kPi - glorySpanRad - forwardSpanRad, forwardSpanRad},
                                   {gloryCount, middleCount, forwardCount});
}

double PhaseTable::interpolate(int wavelength, double gammaRad) const
{
    const double position = angles.index(gammaRad);
    const int i = std::min(static_cast<int>(position), angles.size() - 2);
    const double f = position - i;
    return (1.0 - f) * at(wavelength, i) + f * at(wavelength, i + 1);
}

glm::dvec3 colourAtAngle(const AngleGrid& grid, const std::vector<glm::dvec3>& colours, double gammaRad)
{
    const double position = grid.index(gammaRad);
    const size_t i = std::min(static_cast<size_t>(position), colours.size() - 2);
    return glm::mix(colours[i], colours[i + 1], position - double(i));
}

double phaseTableWork(const mie::DropSizeDistribution& drops, const GloryTableSpec& spec)
{
    const PhaseTable table = emptyPhaseTable(spec);
    const auto [lo, hi] = drops.radiusRangeUm();
    double terms = 0.0;
    for (const double wavelengthNm : table.wavelengthsNm) {
        const double k = 2.0 * physics::kPi / (wavelengthNm * 1e-3);
        const double nodes = drops.isSingleSize() ? 1.0 : radiusIntervals(k, lo, hi, spec.sizeParameterStep) + 1.0;
        terms += nodes * mie::wiscombeTermCount(k * 0.5 * (lo + hi)); // the series' length grows as x
    }
    return terms * spec.angles.size();
}

PhaseTable emptyPhaseTable(const GloryTableSpec& spec)
{
    PhaseTable table;
    table.angles = spec.angles;
    for (int w = 0; w < spec.wavelengthCount; ++w)
        table.wavelengthsNm.push_back(spec.wavelengthCount == 1
                                          ? spec.firstNm
                                          : spec.firstNm + (spec.lastNm - spec.firstNm) * w / (spec.wavelengthCount - 1));
    table.values.assign(size_t(spec.wavelengthCount) * size_t(spec.angles.size()), 0.0);
    return table;
}

PhaseTable phaseTable(const mie::DropSizeDistribution& drops, const GloryTableSpec& spec)
{
    PhaseTable table = emptyPhaseTable(spec);
    const double largestX = 2.0 * physics::kPi * drops.radiusRangeUm().second / (spec.firstNm * 1e-3);
    const AngularFunctions functions(spec.angles, mie::wiscombeTermCount(largestX));

    std::vector<long long> series(size_t(spec.wavelengthCount), 0);
    const int threads = std::max(1, std::min(spec.wavelengthCount, spec.threads > 0 ? spec.threads
                                                                                       : int(std::thread::hardware_concurrency())));
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
        pool.emplace_back([&, t] {
            for (int w = t; w < spec.wavelengthCount; w += threads)
                series[size_t(w)] = phaseRow(drops, table.wavelengthsNm[size_t(w)], functions, spec.sizeParameterStep,
                                             table.values.data() + size_t(w) * size_t(spec.angles.size()));
        });
    for (std::thread& t : pool)
        t.join();
    for (long long s : series)
        table.mieSeries += s;
    return table;
}

PhaseTable smearedByDisc(const PhaseTable& table, double discRadiusRad)
{
    if (discRadiusRad <= 0.0)
        return table;
    PhaseTable smeared = table;
    const auto& nodes = boost::math::quadrature::gauss<double, 8>::abscissa();
    const auto& weights = boost::math::quadrature::gauss<double, 8>::weights();
    constexpr int kAzimuths = 24;
    // Gauss–Legendre on [0, ρ] for ∫ f(s) s ds: Boost stores the non-negative nodes of [−1, 1].
    std::vector<double> radii, radiusWeights;
    for (size_t i = 0; i < nodes.size(); ++i)
        for (double sign : {-1.0, 1.0}) {
            if (nodes[i] == 0.0 && sign < 0.0)
                continue;
            const double s = 0.5 * discRadiusRad * (1.0 + sign * nodes[i]);
            radii.push_back(s);
            radiusWeights.push_back(0.5 * discRadiusRad * weights[i] * s);
        }
    double total = 0.0;
    for (double w : radiusWeights)
        total += w * kAzimuths;
    const int angles = table.angles.size();
    for (int a = 0; a < angles; ++a) {
        const double gamma = table.angles.angle(a);
        std::vector<double> sum(table.wavelengthsNm.size(), 0.0);
        for (size_t i = 0; i < radii.size(); ++i)
            for (int j = 0; j < kAzimuths; ++j) {
                const double phi = physics::kPi * (j + 0.5) / kAzimuths;
                const double c = std::cos(gamma) * std::cos(radii[i]) + std::sin(gamma) * std::sin(radii[i]) * std::cos(phi);
                const double offset = std::acos(std::clamp(c, -1.0, 1.0));
                for (size_t w = 0; w < sum.size(); ++w)
                    sum[w] += radiusWeights[i] * table.interpolate(int(w), offset);
            }
        for (size_t w = 0; w < sum.size(); ++w)
            smeared.values[w * size_t(angles) + size_t(a)] = sum[w] / total;
    }
    return smeared;
}

std::vector<glm::dvec3> gloryXyz(const PhaseTable& table, const LightSource& light)
{
    const size_t count = table.wavelengthsNm.size();
    const LightSpectrum spectrum = light.spectrum();
    std::vector<glm::dvec3> weight(count, glm::dvec3(0.0)); // 683 E(λ) cmf(λ) Δλ / 4π
    for (size_t w = 0; w < count; ++w) {
        const double step = count == 1 ? 1.0
                                       : (table.wavelengthsNm.back() - table.wavelengthsNm.front()) / double(count - 1) *
                                             ((w == 0 || w + 1 == count) ? 0.5 : 1.0);
        const double nm = table.wavelengthsNm[w];
        weight[w] = physics::kLumensPerWatt * spectrum(nm) * physics::colourMatching(nm) * step / (4.0 * physics::kPi);
    }
    std::vector<glm::dvec3> xyz(size_t(table.angles.size()), glm::dvec3(0.0));
    for (int a = 0; a < table.angles.size(); ++a)
        for (size_t w = 0; w < count; ++w)
            xyz[size_t(a)] += weight[w] * table.at(int(w), a);
    return xyz;
}

std::vector<glm::dvec3> gloryLinearSrgb(const std::vector<glm::dvec3>& xyz)
{
    std::vector<glm::dvec3> rgb;
    rgb.reserve(xyz.size());
    for (const glm::dvec3& c : xyz)
        rgb.push_back(physics::desaturateIntoGamut(physics::xyzToLinearSrgb(c)));
    return rgb;
}

} // namespace aurorawall::components::glory::optics
