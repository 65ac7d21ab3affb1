#include "components/aurora/physics/curtain_geometry.h"

#include "physics/constants.h"
#include "common/glsl.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace aurorawall::components::aurora::physics {
namespace {

namespace f64 {
AURORAWALL_GLSL_PRECISION(double)
#include "render/angle.glsl"
} // namespace f64
using f64::angleBetween;

// One span of the centripetal Catmull–Rom spline as a cubic Hermite curve on u ∈ [0, 1]:
// Q(u) = h00 P1 + h10 m1 + h01 P2 + h11 m2 with the Barry–Goldman tangents for knots t0 < t1 < t2 < t3,
// t_{i+1} − t_i = |P_{i+1} − P_i|^(1/2) (Yuksel, Schaefer & Keyser, "Parameterization and applications of
// Catmull–Rom curves", CAD 2011):
//   m1 = (t2 − t1) [(P1 − P0)/(t1 − t0) − (P2 − P0)/(t2 − t0) + (P2 − P1)/(t2 − t1)]
//   m2 = (t2 − t1) [(P2 − P1)/(t2 − t1) − (P3 − P1)/(t3 − t1) + (P3 − P2)/(t3 − t2)]
struct Span {
    glm::dvec3 p1, p2, m1, m2;

    Span(const glm::dvec3& p0, const glm::dvec3& p1_, const glm::dvec3& p2_, const glm::dvec3& p3)
        : p1(p1_), p2(p2_)
    {
        const double d0 = std::sqrt(glm::length(p1 - p0));
        const double d1 = std::sqrt(glm::length(p2 - p1));
        const double d2 = std::sqrt(glm::length(p3 - p2));
        m1 = d1 * ((p1 - p0) / d0 - (p2 - p0) / (d0 + d1) + (p2 - p1) / d1);
        m2 = d1 * ((p2 - p1) / d1 - (p3 - p1) / (d1 + d2) + (p3 - p2) / d2);
    }

    // Hermite basis h00 = 2u³ − 3u² + 1, h10 = u³ − 2u² + u, h01 = −2u³ + 3u², h11 = u³ − u².
    glm::dvec3 q(double u) const
    {
        const double u2 = u * u, u3 = u2 * u;
        return (2 * u3 - 3 * u2 + 1) * p1 + (u3 - 2 * u2 + u) * m1 + (-2 * u3 + 3 * u2) * p2 + (u3 - u2) * m2;
    }

    // dQ/du from the derivatives of the Hermite basis.
    glm::dvec3 dq(double u) const
    {
        const double u2 = u * u;
        return (6 * u2 - 6 * u) * p1 + (3 * u2 - 4 * u + 1) * m1 + (-6 * u2 + 6 * u) * p2 + (3 * u2 - 2 * u) * m2;
    }

    // The curve on the unit sphere is C = Q/|Q|; its velocity is dC/du = (Q' − C (C·Q'))/|Q|.
    glm::dvec3 velocity(double u) const
    {
        const glm::dvec3 qu = q(u), d = dq(u);
        const double r = glm::length(qu);
        const glm::dvec3 c = qu / r;
        return (d - c * glm::dot(c, d)) / r;
    }

    double speed(double u) const { return glm::length(velocity(u)); }

    // ∫_a^b |dC/du| du by 5-point Gauss–Legendre (Abramowitz & Stegun 25.4.29, Table 25.4).
    double arclength(double a, double b) const
    {
        static const double x[5] = {0.0, -0.5384693101056830910, 0.5384693101056830910, -0.9061798459386639928,
                                    0.9061798459386639928};
        static const double w[5] = {0.5688888888888888889, 0.4786286704993664680, 0.4786286704993664680,
                                    0.2369268850561890875, 0.2369268850561890875};
        const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
        double sum = 0.0;
        for (int i = 0; i < 5; ++i)
            sum += w[i] * speed(mid + half * x[i]);
        return half * sum;
    }
};

// Composite Gauss–Legendre panels per span; the unit-sphere speed is analytic on the span, so 32 panels of
// degree-9 exactness reach double precision for spans under 90°.
constexpr int kPanels = 32;

} // namespace

// Inverting x = −cos φ cos λ, y = −cos φ sin λ, z = sin φ: φ = atan2(z, √(x² + y²)), λ = atan2(−y, −x).
glm::dvec2 latLonFromUnit(const glm::dvec3& unit)
{
    return {std::atan2(unit.z, std::hypot(unit.x, unit.y)) / aurorawall::physics::kDegree, std::atan2(-unit.y, -unit.x) / aurorawall::physics::kDegree};
}

// Each span between control points is split into m = ceil(L/spacing) pieces of equal spline arclength L/m.
// The parameter of arclength σ solves S(u) = σ by Newton's method, S' = |dC/du|, inside the Gauss–Legendre
// panel that holds σ.
CurtainPolyline sampleCurtain(const std::vector<glm::dvec2>& latLonDeg, double planetRadiusKm, double spacingKm)
{
    if (latLonDeg.size() < 2)
        throw std::invalid_argument("sampleCurtain: a curtain needs at least 2 control points");
    if (!(planetRadiusKm > 0.0) || !(spacingKm > 0.0))
        throw std::invalid_argument("sampleCurtain: planet radius and spacing must be positive");
    const int n = static_cast<int>(latLonDeg.size());
    std::vector<glm::dvec3> p(n + 2); // p[k + 1] is control point k; p[0] and p[n + 1] are the phantoms
    for (int k = 0; k < n; ++k)
        p[k + 1] = common::unitFromLatLon(latLonDeg[k].x, latLonDeg[k].y);
    for (int k = 1; k < n; ++k) {
        const double angle = angleBetween(p[k], p[k + 1]);
        if (!(angle > 0.0) || !(angle < 0.5 * aurorawall::physics::kPi))
            throw std::invalid_argument("sampleCurtain: consecutive control points must be distinct and less than 90° apart");
    }
    p[0] = 2.0 * p[1] - p[2];
    p[n + 1] = 2.0 * p[n] - p[n - 1];

    CurtainPolyline out;
    out.planetRadiusKm = planetRadiusKm;
    double start = 0.0; // arclength of the span's first point, km
    for (int k = 0; k + 1 < n; ++k) {
        const Span span(p[k], p[k + 1], p[k + 2], p[k + 3]);
        double cumulative[kPanels + 1] = {0.0}; // arclength on the unit sphere at u = i/kPanels
        for (int i = 0; i < kPanels; ++i)
            cumulative[i + 1] = cumulative[i] + span.arclength(double(i) / kPanels, double(i + 1) / kPanels);
        const double length = cumulative[kPanels];
        const int pieces = std::max(1, static_cast<int>(std::ceil(length * planetRadiusKm / spacingKm)));
        out.controlPointIndex.push_back(static_cast<int>(out.points.size()));
        // The parameter u of unit-sphere arclength sigma within the span.
        auto parameterAt = [&](double sigma) {
            const int panel = std::clamp(
                static_cast<int>(std::upper_bound(cumulative, cumulative + kPanels + 1, sigma) - cumulative) - 1, 0,
                kPanels - 1);
            const double lo = double(panel) / kPanels, hi = double(panel + 1) / kPanels;
            double u = lo + (hi - lo) * (sigma - cumulative[panel]) / (cumulative[panel + 1] - cumulative[panel]);
            for (int iteration = 0; iteration < 8; ++iteration) {
                const double step = (cumulative[panel] + span.arclength(lo, u) - sigma) / span.speed(u);
                u = std::clamp(u - step, lo, hi);
                if (std::abs(step) < 1e-15)
                    break;
            }
            return u;
        };
        const int last = k + 2 == n ? pieces : pieces - 1; // the next span starts with this span's end point
        for (int j = 0; j <= last; ++j) {
            const double sigma = length * j / pieces;
            const double u = j == 0 ? 0.0 : j == pieces ? 1.0 : parameterAt(sigma);
            const glm::dvec3 point = j == 0 ? p[k + 1] : j == pieces ? p[k + 2] : glm::normalize(span.q(u));
            const glm::dvec3 tangent = glm::normalize(span.velocity(u));
            out.points.push_back(point);
            out.arclengthKm.push_back((start + sigma) * planetRadiusKm);
            out.normals.push_back(glm::normalize(glm::cross(point, tangent)));
        }
        start += length;
    }
    out.controlPointIndex.push_back(static_cast<int>(out.points.size()) - 1);
    return out;
}

// Slerp (Shoemake, "Animating rotation with quaternion curves", SIGGRAPH 1985):
// p(w) = [sin((1 − w)θ) a + sin(wθ) b] / sin θ, θ the angle between a and b; p = a when θ = 0.
std::vector<glm::dvec2> interpolateControlPoints(const std::vector<glm::dvec2>& a, const std::vector<glm::dvec2>& b,
                                                 double w)
{
    if (a.size() != b.size())
        throw std::invalid_argument("interpolateControlPoints: keyframes have different control point counts");
    std::vector<glm::dvec2> out;
    out.reserve(a.size());
    for (size_t k = 0; k < a.size(); ++k) {
        const glm::dvec3 pa = common::unitFromLatLon(a[k].x, a[k].y), pb = common::unitFromLatLon(b[k].x, b[k].y);
        const double theta = angleBetween(pa, pb);
        if (!(theta < aurorawall::physics::kPi - 1e-9))
            throw std::invalid_argument("interpolateControlPoints: a control point moves to its antipode");
        const glm::dvec3 p = theta == 0.0 ? pa
                                          : (std::sin((1.0 - w) * theta) * pa + std::sin(w * theta) * pb) / std::sin(theta);
        out.push_back(latLonFromUnit(glm::normalize(p)));
    }
    return out;
}

double smoothWeight(double t, double t0, double t1)
{
    const double x = std::clamp((t - t0) / (t1 - t0), 0.0, 1.0);
    return x * x * (3.0 - 2.0 * x);
}

} // namespace aurorawall::components::aurora::physics
