#include "components/aurora/aurora_reference.h"

#include "physics/colour.h"
#include "components/aurora/physics/deposition_table.h"
#include "components/aurora/physics/emission.h"
#include "physics/constants.h"
#include "scene/ray_steps.h"

namespace aurorawall::components::aurora::f64 {
using namespace aurorawall::scene::f64; // the ray and its steps
namespace {
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function" // the reference uses some of the modules' functions
#include "render/angle.glsl"
#include "components/aurora/segment_projection.glsl"
#include "components/aurora/curtain_end.glsl"
#pragma GCC diagnostic pop
} // namespace
} // namespace aurorawall::components::aurora::f64

#include <algorithm>
#include <cmath>
#include <limits>

namespace aurorawall::components::aurora {

AuroraReference::AuroraReference(const Settings& aurora, double planetRadiusKm, double timeS, double stepKm,
                                 const roles::FluxFrames* frames, std::optional<roles::DetailShape> shape,
                                 double stripWidthKm)
    : aurora_(aurora), planetRadiusKm_(planetRadiusKm), stepKm_(stepKm), frames_(frames),
      stripWidthKm_(stripWidthKm), shape_(shape)
{
    model_.emplace(aurora, planetRadiusKm, shape_ ? &*shape_ : nullptr);
    for (CurtainNow& now : model_->at(timeS)) {
        Curtain c;
        c.points = std::move(now.polyline.points);
        c.arclengthKm = std::move(now.polyline.arclengthKm);
        for (size_t j = 0; j + 1 < c.points.size(); ++j)
            c.maxSegmentKm = std::max(c.maxSegmentKm, planetRadiusKm * f64::angleBetween(c.points[j], c.points[j + 1]));
        c.state = now.state;
        c.lateralScale = now.lateralScale;
        c.reachKm = now.reachKm;
        curtains_.push_back(std::move(c));
    }
    for (int line = 0; line < physics::kLineCount; ++line)
        lineRgb_[line] = aurorawall::physics::lineLinearSrgbPerRayleigh(static_cast<aurorawall::physics::EmissionLine>(line));
}

// The nearest point of curtain `c` to footprint direction `unit` and the curtain coordinates
// there, by exact projection on its segments (the shader's projectOnSegment in double, over every
// segment that can be nearest, not only those around the footprint map's point). A point of a segment of length L is within L/2
// of one of its ends, so a segment whose nearer end is farther than (nearest vertex) + L_max/2
// cannot be the nearest: only the others are projected.
AuroraReference::Nearest AuroraReference::nearestOn(const Curtain& c, glm::dvec3 unit) const
{
    const double R = planetRadiusKm_;
    Nearest best;
    double maxDot = -1.0;
    for (const glm::dvec3& p : c.points)
        maxDot = std::max(maxDot, glm::dot(p, unit));
    const double nearestVertex = std::acos(std::clamp(maxDot, -1.0, 1.0));
    // 1 km of slack for the arclength-based segment length the shader's projection uses.
    const double limit = nearestVertex + (0.5 * c.maxSegmentKm + 1.0) / R;
    const double minDot = limit >= aurorawall::physics::kPi ? -2.0 : std::cos(limit);
    for (size_t j = 0; j + 1 < c.points.size(); ++j) {
        const glm::dvec3& a = c.points[j];
        const glm::dvec3& b = c.points[j + 1];
        if (std::max(glm::dot(a, unit), glm::dot(b, unit)) < minDot)
            continue;
        const glm::dvec4 p = f64::projectOnSegment(a, b, c.arclengthKm[j + 1] - c.arclengthKm[j], unit, R);
        const double distance = std::hypot(p.z, p.w);
        if (distance < best.distanceKm) {
            best.distanceKm = distance;
            best.sKm = c.arclengthKm[j] + std::clamp(p.x, 0.0, p.y);
            best.uKm = p.z;
            const double s = c.arclengthKm[j] + p.x;
            best.beyondEndKm = std::max({-s, s - c.arclengthKm.back(), 0.0});
        }
    }
    return best;
}

double AuroraReference::nearestCurtainKm(glm::dvec3 unit) const
{
    double best = std::numeric_limits<double>::infinity();
    for (const Curtain& c : curtains_)
        best = std::min(best, nearestOn(c, unit).distanceKm);
    return best;
}

// curtain_profile.glsl in double: with fluid detail, peakScale x F(s + offset, u x scale, phase)
// (roles::sampleFlux), zero beyond half the strip width; else exp(-(u scale)^2 / 2).
double AuroraReference::profile(const Curtain& c, double sKm, double uKm) const
{
    const double across = uKm * c.lateralScale;
    if (!frames_)
        return std::exp(-0.5 * across * across);
    if (std::abs(across) >= 0.5 * stripWidthKm_)
        return 0.0;
    return shape_->peakScale * roles::sampleFlux(*frames_, sKm + c.state.detailOffsetKm, across, c.state.detailPhase);
}

// curtainEmissionRgbPerKm of curtain_emission.glsl without tables: 1 photon cm^-3 s^-1 over 1 km is
// 0.1 R, so the radiance per km per erg cm^-2 s^-1 is
// sum over lines of 0.1 depositionRate(z, E) lineYield(line, z) lineRgb(line).
glm::dvec3 AuroraReference::emissionRgbPerKm(double altitudeKm, double energyKeV) const
{
    const double deposition = physics::depositionRate(altitudeKm, energyKeV, aurora_.spectrum);
    glm::dvec3 rgb(0.0);
    for (int line = 0; line < physics::kLineCount; ++line)
        rgb += 0.1 * deposition * physics::lineYield(static_cast<physics::EmissionLine>(line), altitudeKm) *
               lineRgb_[line];
    return rgb;
}

// Integral of the emission over [t0, t1] of the ray o + t d (|d| = 1): the midpoint rule with
// steps of stepKm_ where a curtain is within the largest reach, and jumps of (distance - that reach)
// elsewhere: a km along the ray moves the footprint by at most R / |p| <= 1 km on the planet
// (|p| >= R in the shell), so the jump ends at or before the first point within reach.
glm::dvec3 AuroraReference::segment(glm::dvec3 o, glm::dvec3 d, double t0, double t1) const
{
    const double reach = model_->reachKm();
    glm::dvec3 sum(0.0);
    double t = t0;
    while (t < t1) {
        const double gap = nearestCurtainKm(glm::normalize(o + t * d)) - reach;
        if (gap > stepKm_) {
            t += gap;
            continue;
        }
        const double h = std::min(stepKm_, t1 - t);
        const glm::dvec3 p = o + (t + 0.5 * h) * d;
        // Every curtain within its reach emits: overlapping curtains add.
        for (const Curtain& c : curtains_) {
            const Nearest n = nearestOn(c, glm::normalize(p));
            if (n.distanceKm > c.reachKm)
                continue;
            const double flux = c.state.energyFluxErgPerCm2S * profile(c, n.sKm, n.uKm) *
                                f64::curtainEndFade(n.beyondEndKm, c.reachKm);
            if (flux > 0.0)
                sum += flux * h * emissionRgbPerKm(glm::length(p) - planetRadiusKm_, c.state.energyKeV);
        }
        t += h;
    }
    return sum;
}

// shadeAurora of aurora_curtains.glsl in double.
f64::Ray AuroraReference::shade(f64::Ray ray) const
{
    const double R = planetRadiusKm_;
    const f64::ShellSegments shell = f64::rayShell(ray.origin, ray.direction, R + aurora_.bottomKm,
                                                   ray.altitude - aurora_.bottomKm, R + aurora_.topKm,
                                                   ray.altitude - aurora_.topKm, ray.end);
    for (const glm::dvec2 part : {shell.first, shell.second})
        if (part.x < part.y)
            ray.radiance += segment(ray.origin, ray.direction, part.x, part.y) * f64::transmittanceTo(ray, part);
    return ray;
}

} // namespace aurorawall::components::aurora
