#pragma once
// Adaptive Simpson quadrature for the tests: independent of the closed forms and fixed rules under test.
#include <algorithm>
#include <cmath>
#include <functional>

namespace aurorawall::components::aurora::physics::testing {

inline double adaptiveSimpson(const std::function<double(double)>& f, double a, double b, double tolerance,
                              int depth = 0)
{
    double m = 0.5 * (a + b);
    double whole = (b - a) / 6.0 * (f(a) + 4.0 * f(m) + f(b));
    double left = (m - a) / 6.0 * (f(a) + 4.0 * f(0.5 * (a + m)) + f(m));
    double right = (b - m) / 6.0 * (f(m) + 4.0 * f(0.5 * (m + b)) + f(b));
    if (depth > 40 || std::abs(left + right - whole) < 15.0 * tolerance) return left + right + (left + right - whole) / 15.0;
    return adaptiveSimpson(f, a, m, 0.5 * tolerance, depth + 1) + adaptiveSimpson(f, m, b, 0.5 * tolerance, depth + 1);
}

// ∫_a^b f over pieces of at most `piece` (so that no narrow peak slips between the first samples),
// each to a relative tolerance of its own size.
inline double piecewiseSimpson(const std::function<double(double)>& f, double a, double b, double piece,
                               double relativeTolerance)
{
    double sum = 0.0;
    for (double x = a; x < b; x += piece) {
        double end = std::min(x + piece, b);
        double rough = (end - x) * (std::abs(f(x)) + std::abs(f(0.5 * (x + end))) + std::abs(f(end))) / 3.0;
        sum += adaptiveSimpson(f, x, end, relativeTolerance * rough + 1e-300);
    }
    return sum;
}

// Altitude of the maximum of f on [a, b] km: a 0.1 km scan, then golden-section search to 1e-6 km.
inline double peakAltitude(const std::function<double(double)>& f, double a, double b)
{
    double best = a;
    for (double z = a; z <= b; z += 0.1)
        if (f(z) > f(best)) best = z;
    double lo = best - 0.1, hi = best + 0.1;
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    while (hi - lo > 1e-6) {
        double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
        if (f(x1) > f(x2)) hi = x2; else lo = x1;
    }
    return 0.5 * (lo + hi);
}

} // namespace aurorawall::components::aurora::physics::testing
