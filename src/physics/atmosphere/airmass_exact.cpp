#include "physics/atmosphere/airmass_exact.h"

#include "physics/constants.h"

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace aurorawall::physics::atmosphere {
namespace {

constexpr double kDensityExponentCap = 60.0; // as airmassDensity in airmass_common.glsl

// The integrand of one monotone piece, divided by its value at the piece's lower end xLow:
// g(x) = exp(e(x) − e(xLow)), e(x) = min((R − r(x))/H, 60), r(x) = √(x² + y²). While uncapped,
// e(x) − e(xLow) = −(x − xLow)(x + xLow)/((r + rLow)·H), free of cancellation. g ≤ 1 on the piece;
// a node rounded to just below xLow (pieces shorter than an ulp of x) counts as xLow, where a tiny H
// would otherwise make e^{+huge} = inf, and 0/0 (H·r underflowing to 0 at xLow) cannot arise.
struct PieceIntegrand {
    double y, xLow, rLow, H, R;
    bool lowCapped;
    double operator()(double x) const
    {
        double r = std::hypot(x, y);
        if (!lowCapped) {
            const double rise = (x - xLow) * (x + xLow);
            return rise > 0.0 ? std::exp(-rise / ((r + rLow) * H)) : 1.0;
        }
        return std::exp(std::min((R - r) / H - kDensityExponentCap, 0.0));
    }
};

// Gauss–Kronrod 7/15 (Boost.Math; QUADPACK's qk15 rule) on [a, b]: one application when
// maxDepth = 0, else adaptive bisection while the Kronrod–Gauss difference of a subinterval
// exceeds both `relativeTolerance` of its own estimate and its share of `relativeTolerance` of
// [a, b]'s, at most 2^maxDepth subintervals (against rounding noise above the tolerance).
template <class Integrand>
double gaussKronrod(const Integrand& f, double a, double b, unsigned maxDepth, double relativeTolerance)
{
    return boost::math::quadrature::gauss_kronrod<double, 15>::integrate(f, a, b, maxDepth, relativeTolerance);
}

constexpr unsigned kMaxDepth = 12;

// x ≥ 0 at which the ray reaches radius r (r ≥ y), on the outgoing side.
double distanceAtRadius(double r, double y) { return std::sqrt((r - y) * (r + y)); }

// ∫_{xLow}^{xHigh} exp(e(x)) dx for 0 ≤ xLow < xHigh, where r rises monotonically.
// Split where the radius has risen by H/16, H/8, …, 4096·H above the lowest point, and at the
// planet's surface and the cap radius, so that no subinterval hides a narrow spike of the integrand.
double monotonePiece(double y, double xLow, double xHigh, double H, double R)
{
    double rLow = std::hypot(xLow, y);
    double capRadius = R - kDensityExponentCap * H;
    PieceIntegrand f{y, xLow, rLow, H, R, rLow < capRadius};
    std::vector<double> splits{xLow, xHigh};
    double baseRadius = std::max(rLow, capRadius);
    for (double rise = H / 16.0; rise <= 4096.0 * H; rise *= 2.0) {
        splits.push_back(distanceAtRadius(baseRadius + rise, y));
    }
    if (R > y) splits.push_back(distanceAtRadius(R, y));
    if (capRadius > y) splits.push_back(distanceAtRadius(capRadius, y));
    std::sort(splits.begin(), splits.end());
    splits.erase(std::remove_if(splits.begin(), splits.end(),
                                [&](double x) { return !(x >= xLow && x <= xHigh); }),
                 splits.end());
    splits.erase(std::unique(splits.begin(), splits.end()), splits.end());

    // Every subinterval to 1e-14 of the whole piece: first each one's single-rule estimate.
    std::vector<double> rough(splits.size() - 1);
    double roughTotal = 0.0;
    for (size_t i = 0; i + 1 < splits.size(); ++i) {
        rough[i] = gaussKronrod(f, splits[i], splits[i + 1], 0, 0.0);
        roughTotal += rough[i];
    }
    double total = 0.0;
    for (size_t i = 0; i + 1 < splits.size(); ++i) {
        if (rough[i] > 0.0) total += gaussKronrod(f, splits[i], splits[i + 1], kMaxDepth, 1e-14 * roughTotal / rough[i]);
    }
    double lowExponent = std::min((R - rLow) / H, kDensityExponentCap);
    return std::exp(lowExponent) * total;
}

} // namespace

double exactAirmass(glm::dvec3 origin, glm::dvec3 direction, double t0, double t1, double H, double R)
{
    double directionLength = glm::length(direction);
    if (!(directionLength > 0.0) || t0 == t1) return 0.0;
    glm::dvec3 d = direction / directionLength;
    if (std::abs(t1 - t0) <= H) {
        // Shorter than a scale height: integrate in t with |o + t·d̂| taken directly, since x = t − t_c
        // cannot resolve a segment much shorter than |t_c| (the exponent varies by at most 1 here).
        auto density = [&](double t) { return std::exp(std::min((R - glm::length(origin + t * d)) / H, kDensityExponentCap)); };
        // The radius carries rounding of ~1e-16·|o|: a tolerance below that noise cannot be met.
        double tolerance = std::max(1e-13, 1e-14 * glm::length(origin) / H);
        double airmass = gaussKronrod(density, std::min(t0, t1), std::max(t0, t1), kMaxDepth, tolerance);
        return t1 < t0 ? -airmass : airmass;
    }
    double originDistance = glm::length(origin);
    glm::dvec3 up = originDistance > 0.0 ? origin / originDistance : d;
    double y = originDistance * glm::length(up - d) * glm::length(up + d) * 0.5; // see airmassRayFrame
    double tClosest = -glm::dot(origin, d);
    double lo = std::min(t0, t1) - tClosest;
    double hi = std::max(t0, t1) - tClosest;
    double airmass;
    if (lo >= 0.0) {
        airmass = monotonePiece(y, lo, hi, H, R);
    } else if (hi <= 0.0) {
        airmass = monotonePiece(y, -hi, -lo, H, R);
    } else {
        airmass = monotonePiece(y, 0.0, -lo, H, R) + monotonePiece(y, 0.0, hi, H, R);
    }
    return t1 < t0 ? -airmass : airmass;
}

double exactAirmass(const AirmassRay& ray)
{
    return exactAirmass(ray.origin, ray.direction, ray.t0, ray.t1, ray.scaleHeight, ray.planetRadius);
}

// Ch(x, χ) = I / (H·e^{−(r−R)/H}) with H = 1, R = r = x: the ray from (0, 0, x) at zenith angle χ to
// where it has risen 300 scale heights (e^{−300} is far below the quadrature's accuracy).
double exactChapman(double x, double zenithAngle)
{
    glm::dvec3 origin(0.0, 0.0, x);
    glm::dvec3 direction(std::sin(zenithAngle), 0.0, std::cos(zenithAngle));
    double top = x + 300.0;
    double y = x * std::sin(zenithAngle);
    double tTop = std::sqrt((top - y) * (top + y)) - x * std::cos(zenithAngle);
    return exactAirmass(origin, direction, 0.0, tTop, 1.0, x);
}

// e^x·K₁(x) ~ √(π/(2x))·Σ_k a_k/x^k, a_0 = 1, a_k = a_{k−1}·(4 − (2k − 1)²)/(8k)  (A&S 9.7.2, ν = 1).
double scaledBesselK1(double x)
{
    if (x < 500.0) return std::cyl_bessel_k(1.0, x) * std::exp(x);
    double term = 1.0;
    double sum = 1.0;
    for (int k = 1; k < 30 && std::abs(term) > 1e-18; ++k) {
        term *= (4.0 - (2.0 * k - 1.0) * (2.0 * k - 1.0)) / (8.0 * k * x);
        sum += term;
    }
    return std::sqrt(physics::kPi / (2.0 * x)) * sum;
}

} // namespace aurorawall::physics::atmosphere
