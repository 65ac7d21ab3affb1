// Exact Mie scattering (src/components/glory/mie) against published values (Wiscombe 1980, NCAR/TN-140
// and Appl. Opt. 19, 1505: MIEV0's test cases; Bohren & Huffman 1983, Appendix A, BHMIE's example),
// closed forms (the exact-angle sums, the Rayleigh and anomalous-diffraction limits) and itself
// (convergence of the series and of the recurrence start).
#include "physics/constants.h"
#include "components/glory/mie/drop_size_distribution.h"
#include "components/glory/mie/mie_coefficients.h"
#include "components/glory/mie/mie_scattering.h"
#include "components/glory/mie/phase_function.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <vector>

namespace aurorawall::components::glory::mie {
namespace {

Efficiencies efficienciesAt(double x, RefractiveIndex m, const SeriesSettings& settings = {})
{
    return efficiencies(mieCoefficients(x, m, settings));
}

// Published values carry 7 significant digits: half a unit in the last one, relative.
void expectPublished(const char* what, double ours, double published, double halfUnit)
{
    std::printf("%-28s published %-14.7g ours %.10g\n", what, published, ours);
    EXPECT_NEAR(ours, published, halfUnit) << what;
}

TEST(Mie, WiscombeNonAbsorbingX10)
{
    const Efficiencies q = efficienciesAt(10.0, {1.5, 0.0});
    expectPublished("m=1.5 x=10 Qext", q.extinction, 2.881999, 0.5e-6);
    expectPublished("m=1.5 x=10 g", q.asymmetry, 0.742913, 0.5e-6);
}

TEST(Mie, WiscombeWaterX100)
{
    const MieCoefficients c = mieCoefficients(100.0, {1.33, 1e-5});
    const Efficiencies q = efficiencies(c);
    expectPublished("water x=100 Qext", q.extinction, 2.101321, 0.5e-6);
    expectPublished("water x=100 Qsca", q.scattering, 2.096594, 0.5e-6);
    expectPublished("water x=100 g", q.asymmetry, 0.868959, 0.5e-6);
    const Amplitudes forward = amplitudesAtCosine(c, 1.0), backward = amplitudesAtCosine(c, -1.0);
    expectPublished("water x=100 Re S1(0)", forward.s1.real(), 5253.302, 0.5e-3);
    expectPublished("water x=100 Im S1(0)", forward.s1.imag(), -124.3188, 0.5e-4);
    expectPublished("water x=100 Re S1(180)", backward.s1.real(), -56.59205, 0.5e-5);
    expectPublished("water x=100 Im S1(180)", backward.s1.imag(), 46.50974, 0.5e-5);
}

TEST(Mie, BohrenHuffmanExample)
{
    const double x = 2.0 * aurorawall::physics::kPi * 0.525 / 0.6328;
    const Efficiencies q = efficienciesAt(x, {1.55, 0.0});
    expectPublished("B&H Qext", q.extinction, 3.10543, 0.5e-5);
    expectPublished("B&H Qsca", q.scattering, 3.10543, 0.5e-5);
    expectPublished("B&H g", q.asymmetry, 0.63314, 0.5e-5);
}

// The recurrences at μ = ±1 against the closed forms; S2 = S1 forward and −S1 backward. At |μ| = 1,
// πₙ and τₙ are ~n²/2 and τₙ is a difference of two terms ~n³, so each term of the sum carries ~n ulps:
// the tolerance is 4 N ulps of the sum of the terms' magnitudes.
TEST(Mie, ExactAnglesMatchTheClosedForms)
{
    for (double x : {0.5, 10.0, 100.0, 3000.0}) {
        const MieCoefficients c = mieCoefficients(x, {1.33, 0.01});
        const Amplitudes forward = amplitudes(c, {0.0})[0], backward = amplitudes(c, {aurorawall::physics::kPi})[0];
        const std::complex<double> s0 = forwardAmplitude(c), s180 = backwardAmplitudeS1(c);
        double termMagnitudes = 0.0;
        for (size_t i = 0; i < c.a.size(); ++i) termMagnitudes += 0.5 * (2.0 * i + 3.0) * (std::abs(c.a[i]) + std::abs(c.b[i]));
        const double tolerance = 4.0 * double(c.a.size()) * 2.2e-16 * termMagnitudes;
        EXPECT_LT(std::abs(forward.s1 - s0), tolerance) << x;
        EXPECT_LT(std::abs(forward.s2 - s0), tolerance) << x;
        EXPECT_LT(std::abs(backward.s1 - s180), tolerance) << x;
        EXPECT_LT(std::abs(backward.s2 + s180), tolerance) << x;
        // Optical theorem: Qext = 4 Re S(0)/x².
        EXPECT_NEAR(4.0 * s0.real() / (x * x), efficiencies(c).extinction, 1e-12) << x;
    }
}

// Rayleigh: Qsca = (8/3) x⁴ |(m²−1)/(m²+2)|², Qabs = 4x Im((m²−1)/(m²+2)) with m = n − ik (so −Im);
// the next terms are O(|m|²x²) relative (Bohren & Huffman §5.2), so the tolerance is 2|m|²x², plus
// the series' cancellation in double, about 2^-53/x² of Qsca (held with a factor 16): the reason the
// mie command accepts x from 1e-4 up (at x = 1e-6 that cancellation is already 1e-4).
TEST(Mie, RayleighLimitAtSmallX)
{
    for (double x : {1e-3, 1e-4})
    for (RefractiveIndex index : {RefractiveIndex{1.5, 0.0}, RefractiveIndex{1.33, 0.1}, RefractiveIndex{3.0, 10.0}}) {
        const std::complex<double> m = index.m(), polarisability = (m * m - 1.0) / (m * m + 2.0);
        const Efficiencies q = efficienciesAt(x, index);
        const double rayleighScattering = 8.0 / 3.0 * std::pow(x, 4) * std::norm(polarisability);
        const double rayleighAbsorption = -4.0 * x * polarisability.imag();
        std::printf("Rayleigh x=%g m=%g-%gi: Qsca %.10g vs %.10g, Qabs %.10g vs %.10g, g %.3g\n", x, index.n, index.k,
                    q.scattering, rayleighScattering, q.absorption(), rayleighAbsorption, q.asymmetry);
        const double tolerance = 2.0 * std::norm(m) * x * x + 16.0 * std::ldexp(1.0, -53) / (x * x);
        EXPECT_NEAR(q.scattering / rayleighScattering, 1.0, tolerance);
        if (index.k > 0.0) {
            EXPECT_NEAR(q.absorption() / rayleighAbsorption, 1.0, tolerance);
        }
        EXPECT_NEAR(q.asymmetry, 0.0, 1e-4);
    }
}

TEST(Mie, WiscombeTermCount)
{
    EXPECT_EQ(wiscombeTermCount(1e-3), 1);
    EXPECT_EQ(wiscombeTermCount(1.0), 6);            // 1 + 4 + 1
    EXPECT_EQ(wiscombeTermCount(8.0), 17);           // 8 + 8 + 1
    EXPECT_EQ(wiscombeTermCount(10.0), 20);          // 10 + 4.05·2.154 + 2 = 20.73
    EXPECT_EQ(wiscombeTermCount(100.0), 120);        // 100 + 18.80 + 2
    EXPECT_EQ(wiscombeTermCount(1e4), 10088);        // 1e4 + 86.18 + 2
    EXPECT_EQ(wiscombeTermCount(2e4), 20110);        // 2e4 + 108.57 + 2
    EXPECT_EQ(int(mieCoefficients(100.0, {1.33, 0.0}).a.size()), 120);
}

// Terms beyond Wiscombe's count change nothing that matters: the series has converged.
TEST(Mie, TermCountIsConverged)
{
    for (double x : {1.0, 10.0, 100.0, 1e3, 1e4}) {
        SeriesSettings more;
        more.terms = wiscombeTermCount(x) + 50;
        const Efficiencies q = efficienciesAt(x, {1.33, 1e-5}), qMore = efficienciesAt(x, {1.33, 1e-5}, more);
        EXPECT_NEAR(q.extinction / qMore.extinction, 1.0, 1e-9) << x;
        EXPECT_NEAR(q.scattering / qMore.scattering, 1.0, 1e-9) << x;
        EXPECT_NEAR(q.asymmetry, qMore.asymmetry, 1e-9) << x;
    }
}

// Dₙ(mx) started by the continued fraction 15 above max(N, |mx|) against the zero start 10⁴ above:
// the same Qsca. The zero start only 15 above is visibly wrong (0.34% for water at x = 10⁴), so this
// comparison does see a start that is too low.
TEST(Mie, RecurrenceStartIsConvergedAtX1e4)
{
    const double x = 1e4;
    const RefractiveIndex water{1.33, 1e-5};
    SeriesSettings high, zeroLow;
    high.start = RecurrenceStart::Zero;
    high.startAbove = 10000;
    zeroLow.start = RecurrenceStart::Zero;
    const double qsca = efficienciesAt(x, water).scattering;
    const double qscaHigh = efficienciesAt(x, water, high).scattering;
    const double qscaZeroLow = efficienciesAt(x, water, zeroLow).scattering;
    std::printf("x=1e4 water Qsca: continued fraction %.12g, zero start +1e4 %.12g, zero start +15 %.12g (%.3g%%)\n",
                qsca, qscaHigh, qscaZeroLow, 100.0 * (qscaZeroLow / qsca - 1.0));
    EXPECT_LT(std::abs(qsca / qscaHigh - 1.0), 1e-10);
    EXPECT_GT(std::abs(qscaZeroLow / qsca - 1.0), 3e-3);
}

bool finite(const Efficiencies& q)
{
    return std::isfinite(q.extinction) && std::isfinite(q.scattering) && std::isfinite(q.backscatter) &&
           std::isfinite(q.asymmetry);
}

bool finite(const Amplitudes& s)
{
    return std::isfinite(s.s1.real()) && std::isfinite(s.s1.imag()) && std::isfinite(s.s2.real()) &&
           std::isfinite(s.s2.imag());
}

// Stiff and extreme cases: finite everywhere, with the limits they tend to.
TEST(Mie, ExtremeCasesAreFinite)
{
    for (double x : {1e-4, 1e-3, 0.1, 10.0, 1e3, 2e4})
        for (RefractiveIndex m : {RefractiveIndex{1.0 + 1e-7, 0.0}, RefractiveIndex{1.33, 0.0},
                                  RefractiveIndex{3.0, 0.0}, RefractiveIndex{1.5, 10.0}, RefractiveIndex{3.0, 10.0}}) {
            const MieCoefficients c = mieCoefficients(x, m);
            EXPECT_TRUE(finite(efficiencies(c))) << x << " " << m.n << " " << m.k;
            for (double mu : {1.0, 0.5, 0.0, -1.0}) EXPECT_TRUE(finite(amplitudesAtCosine(c, mu))) << x << " " << mu;
        }
}

// Extinction paradox: a large sphere removes twice its geometric cross-section, plus the edge term
// 1.9923861 x^(−2/3) of the asymptotic expansion (Nussenzveig & Wiscombe 1980, Phys. Rev. Lett. 45, 1490),
// 2.7e-3 at x = 2e4; what remains is of order x^(−4/3) and the ripple.
double extinctionAsymptote(double x) { return 2.0 + 1.9923861 * std::pow(x, -2.0 / 3.0); }

TEST(Mie, LargeWeaklyAbsorbingSphereTendsToTwo)
{
    for (double x : {1e4, 2e4}) {
        const Efficiencies q = efficienciesAt(x, {1.33, 1e-5});
        std::printf("x=%g water: Qext %.10g, 2 + edge term %.10g\n", x, q.extinction, extinctionAsymptote(x));
        EXPECT_NEAR(q.extinction, extinctionAsymptote(x), 3e-4);
        EXPECT_NEAR(q.extinction, 2.0, 5e-3);
    }
}

TEST(Mie, NonAbsorbingSphereScattersAllItRemoves)
{
    for (double x : {0.1, 1.0, 10.0, 100.0})
        for (double n : {1.01, 1.33, 2.0, 3.0}) {
            const Efficiencies q = efficienciesAt(x, {n, 0.0});
            EXPECT_NEAR(q.scattering / q.extinction, 1.0, 1e-12) << x << " " << n;
        }
}

TEST(Mie, StronglyAbsorbingSphere)
{
    // k = 10 reflects most of the light that meets the sphere: scattering (diffraction + reflection)
    // exceeds 1, absorption is small but positive, and the extinction still tends to 2.
    const Efficiencies q = efficienciesAt(2e4, {3.0, 10.0});
    std::printf("x=2e4 m=3-10i: Qext %.10g Qsca %.10g g %.6g\n", q.extinction, q.scattering, q.asymmetry);
    EXPECT_NEAR(q.extinction, extinctionAsymptote(2e4), 2e-3);
    EXPECT_GT(q.scattering, 1.5);
    EXPECT_GT(q.absorption(), 0.0);
}

// m → 1: anomalous diffraction (van de Hulst 1957, §11.22) gives Qext = 2 − (4/p) sin p + (4/p²)(1 − cos p)
// = p²/2 − p⁴/36 + …, p = 2x(n − 1), exact for x ≫ 1 as n → 1; the correction at finite x is O(1/x).
TEST(Mie, NearlyIndexMatchedSphereFollowsAnomalousDiffraction)
{
    const double n = 1.0 + 1e-6;
    for (auto [x, tolerance] : {std::pair{10.0, 0.05}, std::pair{100.0, 0.002}}) {
        const double p = 2.0 * x * (n - 1.0), anomalousDiffraction = p * p / 2.0;
        const double qext = efficienciesAt(x, {n, 0.0}).extinction;
        std::printf("m=1+1e-6 x=%g: Qext %.6g, anomalous diffraction %.6g\n", x, qext, anomalousDiffraction);
        EXPECT_NEAR(qext / anomalousDiffraction, 1.0, tolerance);
    }
}

// Gauss–Legendre nodes and weights on [−1, 1] by Newton's method on Pₙ (Golub–Welsch would do too).
void gaussLegendre(int count, std::vector<double>& nodes, std::vector<double>& weights)
{
    nodes.resize(count);
    weights.resize(count);
    for (int i = 0; i < count; ++i) {
        double z = std::cos(aurorawall::physics::kPi * (i + 0.75) / (count + 0.5)), derivative = 0.0;
        for (int iteration = 0; iteration < 100; ++iteration) {
            double p0 = 1.0, p1 = z;
            for (int k = 2; k <= count; ++k) {
                const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            derivative = count * (z * p1 - p0) / (z * z - 1.0);
            const double step = p1 / derivative;
            z -= step;
            if (std::abs(step) < 1e-16) break;
        }
        nodes[i] = z;
        weights[i] = 2.0 / ((1.0 - z * z) * derivative * derivative);
    }
}

// ∫ P dΩ/4π = ½ ∫ P dμ: P of one size is a polynomial in μ of degree 2N, integrated exactly by Gauss–Legendre
// with more than N nodes; the size average is a sum of such polynomials.
double normalisation(const PhaseFunction& p, const std::vector<double>& weights)
{
    double sum = 0.0;
    for (size_t i = 0; i < weights.size(); ++i) sum += 0.5 * weights[i] * p.value[i];
    return sum;
}

TEST(PhaseFunction, IsNormalised)
{
    std::vector<double> mu, weights;
    gaussLegendre(100, mu, weights); // exact to degree 199: N ≤ 99 terms, x up to ~75
    std::vector<double> angles;
    for (double m : mu) angles.push_back(std::acos(m));
    const double wavelength = 0.55;
    const RefractiveIndex water{1.333, 0.0};
    const PhaseFunction single = sizeAveragedPhaseFunction(DropSizeDistribution::singleSize(5.0), wavelength, water, angles);
    EXPECT_NEAR(normalisation(single, weights), 1.0, 1e-12);
    const DropSizeDistribution cloud = DropSizeDistribution::gamma(1.0, 0.1);
    EXPECT_LT(2.0 * aurorawall::physics::kPi / wavelength * cloud.radiusRangeUm().second, 75.0);
    const PhaseFunction averaged = sizeAveragedPhaseFunction(cloud, wavelength, water, angles, 1e-7);
    double worstError = 0.0;
    for (size_t i = 0; i < angles.size(); ++i) worstError = std::max(worstError, averaged.errorEstimate[i] / averaged.value[i]);
    std::printf("gamma r_eff=1 um v_eff=0.1: normalisation - 1 = %.2e, %d Mie sums, worst estimated relative error %.1e\n",
                normalisation(averaged, weights) - 1.0, averaged.mieEvaluations, worstError);
    EXPECT_NEAR(normalisation(averaged, weights), 1.0, 1e-6);
    EXPECT_LT(worstError, 1e-6);
}

// As v_eff → 0 the gamma distribution narrows to its effective radius: the difference to a single size
// shrinks in proportion to v_eff (the spread in radius is √v_eff·r_eff, and P is smooth in r to second order).
TEST(PhaseFunction, NarrowGammaTendsToTheSingleSize)
{
    std::vector<double> angles;
    for (double degrees : {0.0, 10.0, 30.0, 90.0, 140.0, 170.0, 180.0}) angles.push_back(degrees * aurorawall::physics::kDegree);
    const RefractiveIndex water{1.333, 0.0};
    const double radius = 1.0, wavelength = 0.55;
    const PhaseFunction single = sizeAveragedPhaseFunction(DropSizeDistribution::singleSize(radius), wavelength, water, angles);
    double previous = 1e300;
    for (double v : {1e-4, 1e-6, 1e-8}) {
        const PhaseFunction p =
            sizeAveragedPhaseFunction(DropSizeDistribution::gamma(radius, v), wavelength, water, angles, 1e-8);
        double worst = 0.0;
        for (size_t i = 0; i < angles.size(); ++i) worst = std::max(worst, std::abs(p.value[i] / single.value[i] - 1.0));
        std::printf("v_eff=%g: largest relative difference to one size %.3g\n", v, worst);
        EXPECT_LT(worst, 0.2 * previous);
        previous = worst;
    }
    EXPECT_LT(previous, 1e-5);
}

} // namespace
} // namespace aurorawall::components::glory::mie
