// The smooth curtain's column across it (shaders/components/aurora/gaussian_column.glsl, shared
// text) against std::erf / std::erfc in double, including the far tails where 1 − erf cancels.
#include "physics/constants.h"
#include "common/glsl.h"

#include <gtest/gtest.h>

#include <cmath>

namespace aurorawall::f32 {
AURORAWALL_GLSL_PRECISION(float)
#include "components/aurora/gaussian_column.glsl"
} // namespace aurorawall::f32

namespace aurorawall::f64 {
AURORAWALL_GLSL_PRECISION(double)
#include "components/aurora/gaussian_column.glsl"
} // namespace aurorawall::f64

using namespace aurorawall;

namespace {

// ∫ exp(−x²/2) dx over [a, b] in double, written with erfc of the interval's far side so that it
// keeps its relative precision in either tail.
double exactMass(double a, double b)
{
    const double k = std::sqrt(aurorawall::physics::kPi / 2.0), s = 1.0 / std::sqrt(2.0);
    if (a >= 0.0)
        return k * (std::erfc(a * s) - std::erfc(b * s));
    if (b <= 0.0)
        return k * (std::erfc(-b * s) - std::erfc(-a * s));
    return k * (std::erf(b * s) - std::erf(a * s));
}

} // namespace

TEST(GaussianColumn, ErfcWithinItsStatedRelativeError)
{
    for (double x = 0.0; x <= 9.0; x += 0.01)
        EXPECT_NEAR(f64::erfcNonNegative(x) / std::erfc(x), 1.0, 1.2e-7) << x;
}

TEST(GaussianColumn, MassOfIntervalsEverywhere)
{
    const double edges[] = {-12.0, -6.0, -3.0, -1.0, -0.3, 0.0, 0.2, 0.9, 2.5, 4.0, 5.5, 8.0};
    for (double a : edges)
        for (double b : edges) {
            if (a == b)
                continue;
            const double lo = std::min(a, b), hi = std::max(a, b);
            const double exact = (b < a ? -1.0 : 1.0) * exactMass(lo, hi);
            // The fit's 1.2e-7 on each of two tails, relative to the larger tail, over the difference.
            const double tail = std::max(std::erfc(std::min(std::abs(lo), std::abs(hi)) / std::sqrt(2.0)), 1e-300);
            const double allowed = 3e-7 * std::sqrt(aurorawall::physics::kPi / 2.0) * tail + 1e-15;
            EXPECT_NEAR(f64::gaussianMass(a, b), exact, allowed) << a << " " << b;
            // In float: within float rounding of the same (no 1 − erf cancellation in the tails).
            EXPECT_NEAR(f32::gaussianMass(float(a), float(b)), exact, allowed + 2e-6 * std::abs(exact) + 1e-30)
                << a << " " << b;
        }
}

// Far in one tail, where erf(b) − erf(a) in float is 0 or noise, the mass keeps its relative precision.
TEST(GaussianColumn, TailsKeepTheirRelativePrecision)
{
    for (double a : {4.0, 6.0, 8.0, 10.0}) {
        const double b = a + 0.5;
        const double exact = exactMass(a, b);
        EXPECT_NEAR(f32::gaussianMass(float(a), float(b)) / exact, 1.0, 1e-4) << a;
        EXPECT_NEAR(f32::gaussianMass(float(-b), float(-a)) / exact, 1.0, 1e-4) << a;
    }
}

TEST(GaussianColumn, MomentIsTheClosedForm)
{
    for (double a : {-5.0, -1.0, 0.0, 0.5, 3.0})
        for (double b : {-2.0, 0.0, 1.0, 4.0}) {
            // ∫ x exp(−x²/2) dx by Simpson on 2000 panels.
            const int n = 2000;
            const double h = (b - a) / n;
            double sum = 0.0;
            for (int i = 0; i <= n; ++i) {
                const double x = a + i * h;
                sum += (i == 0 || i == n ? 1.0 : (i % 2 ? 4.0 : 2.0)) * x * std::exp(-0.5 * x * x);
            }
            EXPECT_NEAR(f64::gaussianMoment(a, b), sum * h / 3.0, 1e-10) << a << " " << b;
        }
}
