#include "render/reference_ray.h"

#include "atmosphere/airmass_exact.h"
#include "aurora/colour.h"
#include "aurora/curtain_geometry.h"
#include "aurora/deposition_table.h"
#include "aurora/emission.h"
#include "common/constants.h"
#include "common/glsl.h"
#include "render/curtain_detail.h"
#include "render/curtain_frames.h"

#include <algorithm>
#include <limits>
#include <cmath>
#include <stdexcept>

namespace aurorawall::render {

namespace f64 {
AURORAWALL_GLSL_PRECISION(double)
#include "render/ray_sphere.glsl"
#include "render/layers.glsl"
} // namespace f64

namespace {

aurora::Spectrum spectrumOf(const scene::Aurora& a)
{
    return a.spectrum == scene::ElectronSpectrum::Maxwellian ? aurora::Spectrum::Maxwellian
                                                             : aurora::Spectrum::Monoenergetic;
}

// Angle between unit vectors, accurate at all angles (Kahan): 2 atan(|a - b| / |a + b|).
double angleBetween(glm::dvec3 a, glm::dvec3 b)
{
    return 2.0 * std::atan(glm::length(a - b) / glm::length(a + b));
}

// The lateral reach of the fluid frames as render/curtain_detail.cpp computes it: the largest
// |u| + one texel of any cell holding more than 1e-3 of the peak flux (strip km).
double fluidReachKm(const fluid::FluxFrames& f, double stripWidthKm)
{
    float peak = 0.0f;
    for (float v : f.flux)
        peak = std::max(peak, v);
    double reach = 0.0;
    for (int k = 0; k < f.frames; ++k)
        for (int iy = 0; iy < f.ny; ++iy)
            for (int ix = 0; ix < f.nx; ++ix)
                if (f.at(k, ix, iy) > 1e-3f * peak)
                    reach = std::max(reach, std::abs((iy + 0.5) * f.texelKmY - 0.5 * stripWidthKm) + f.texelKmY);
    return reach;
}

} // namespace

ReferenceModel::ReferenceModel(const scene::Scene& scene, double timeS, const fluid::FluxFrames* detail,
                               ReferenceSettings settings)
    : scene_(scene), detail_(detail), settings_(settings)
{
    using scene::Component;
    if (scene.has(Component::Stars) || scene.has(Component::PlanetTexture) || scene.has(Component::Sky))
        throw std::invalid_argument("the reference model has no stars, planet_texture or sky: remove them from the scene");
    if (scene.has(Component::FluidDetail) != (detail != nullptr))
        throw std::invalid_argument("the reference model needs the fluid frames exactly when the scene lists fluid_detail");
    if (!scene.has(Component::Aurora))
        return;
    const scene::Aurora& a = scene.aurora;
    const double R = scene.planet.radiusKm;
    const fluid::CurtainDetailSpec spec = curtainDetailSpec(a.detail);
    fluxWidthKm_ = spec.fluxWidthKm;
    // curtain_detail.cpp: frame 0 is a Gaussian of unit integral; sigma sqrt(2 pi) makes its peak 1.
    peakScale_ = spec.fluxWidthKm * std::sqrt(2.0 * kPi);
    const double detailReach = detail ? fluidReachKm(*detail, spec.stripWidthKm) : 0.0;
    for (const scene::Curtain& curtain : a.curtains) {
        // curtain_field.cpp: lateral scale and reach of each curtain.
        const double sigma = 0.5 * curtain.thicknessKm;
        ReferenceCurtain c;
        c.lateralScale = detail ? spec.fluxWidthKm / sigma : 1.0 / sigma;
        reachKm_ = std::max(reachKm_, detail ? detailReach / c.lateralScale : 4.0 * sigma);
        const CurtainState state = curtainAt(curtain, timeS, detail ? spec.stripLengthKm : 1.0);
        const aurora::CurtainPolyline line = aurora::sampleCurtain(state.controlPointsLatLonDeg, R, a.polylineSpacingKm);
        c.points = line.points;
        c.arclengthKm = line.arclengthKm;
        for (size_t j = 0; j + 1 < c.points.size(); ++j)
            c.maxSegmentKm = std::max(c.maxSegmentKm, R * angleBetween(c.points[j], c.points[j + 1]));
        c.peakFlux = state.energyFluxErgPerCm2S;
        c.energyKeV = state.energyKeV;
        c.detailOffsetKm = state.detailOffsetKm;
        c.detailPhase = state.detailPhase;
        curtains_.push_back(std::move(c));
    }
    for (int line = 0; line < aurora::kLineCount; ++line)
        lineRgb_[line] = aurora::lineLinearSrgbPerRayleigh(static_cast<aurora::EmissionLine>(line));
}

// The nearest point of curtain `ci` to footprint direction `unit` and the curtain coordinates
// there, by exact projection on its segments (segmentProjection of aurora_curtains.glsl in
// double, over every segment that can be nearest). A point of a segment of length L is within L/2
// of one of its ends, so a segment whose nearer end is farther than (nearest vertex) + L_max/2
// cannot be the nearest: only the others are projected.
ReferenceModel::Nearest ReferenceModel::nearestOn(size_t ci, glm::dvec3 unit) const
{
    const double R = scene_.planet.radiusKm;
    const ReferenceCurtain& c = curtains_[ci];
    Nearest best;
    double maxDot = -1.0;
    for (const glm::dvec3& p : c.points)
        maxDot = std::max(maxDot, glm::dot(p, unit));
    const double nearestVertex = std::acos(std::clamp(maxDot, -1.0, 1.0));
    // 1 km of slack for the arclength-based segment length the shader's projection uses.
    const double limit = nearestVertex + (0.5 * c.maxSegmentKm + 1.0) / R;
    const double minDot = limit >= kPi ? -2.0 : std::cos(limit);
    for (size_t j = 0; j + 1 < c.points.size(); ++j) {
        const glm::dvec3& a = c.points[j];
        const glm::dvec3& b = c.points[j + 1];
        if (std::max(glm::dot(a, unit), glm::dot(b, unit)) < minDot)
            continue;
        const glm::dvec3 normal = glm::normalize(glm::cross(a, b));
        const double along = R * std::atan2(glm::dot(glm::cross(a, unit), normal), glm::dot(a, unit));
        const double length = c.arclengthKm[j + 1] - c.arclengthKm[j];
        const double lateral = R * std::asin(std::clamp(glm::dot(unit, normal), -1.0, 1.0));
        const double beyond = std::max({-along, along - length, 0.0});
        const double distance = std::hypot(lateral, beyond);
        if (distance < best.distanceKm) {
            best.curtain = static_cast<int>(ci);
            best.distanceKm = distance;
            best.sKm = c.arclengthKm[j] + std::clamp(along, 0.0, length);
            best.uKm = lateral;
        }
    }
    return best;
}

double ReferenceModel::nearestCurtainKm(glm::dvec3 unit) const
{
    double best = std::numeric_limits<double>::infinity();
    for (size_t ci = 0; ci < curtains_.size(); ++ci)
        best = std::min(best, nearestOn(ci, unit).distanceKm);
    return best;
}

// shaders/aurora/curtain_profile.glsl in double: with fluid detail, peakScale x F(s + offset,
// u x scale, phase) (fluid::sampleFlux), zero beyond half the strip width; else exp(-(u scale)^2 / 2).
double ReferenceModel::profile(const ReferenceCurtain& c, double sKm, double uKm) const
{
    const double across = uKm * c.lateralScale;
    if (!detail_)
        return std::exp(-0.5 * across * across);
    if (std::abs(across) >= 0.5 * scene_.aurora.detail.stripWidthKm)
        return 0.0;
    return peakScale_ * fluid::sampleFlux(*detail_, sKm + c.detailOffsetKm, across, c.detailPhase);
}

// auroraEmissionRgbPerKm of shaders/aurora/deposition.glsl without tables: 1 photon cm^-3 s^-1 over
// 1 km is 0.1 R, so the radiance per km per erg cm^-2 s^-1 is
// sum over lines of 0.1 depositionRate(z, E) lineYield(line, z) lineRgb(line).
glm::dvec3 ReferenceModel::emissionRgbPerKm(double altitudeKm, double energyKeV) const
{
    const double deposition = aurora::depositionRate(altitudeKm, energyKeV, spectrumOf(scene_.aurora));
    glm::dvec3 rgb(0.0);
    for (int line = 0; line < aurora::kLineCount; ++line)
        rgb += 0.1 * deposition * aurora::lineYield(static_cast<aurora::EmissionLine>(line), altitudeKm) * lineRgb_[line];
    return rgb;
}

// Integral of the emission over [t0, t1] of the ray o + t d (|d| = 1): the midpoint rule with
// steps of settings_.stepKm where a curtain is within reach, and jumps of (distance - reach)
// elsewhere: a km along the ray moves the footprint by at most R / |p| <= 1 km on the planet
// (|p| >= R in the shell), so the jump ends at or before the first point within reach.
glm::dvec3 ReferenceModel::auroraSegment(glm::dvec3 o, glm::dvec3 d, double t0, double t1) const
{
    const double R = scene_.planet.radiusKm;
    glm::dvec3 sum(0.0);
    double t = t0;
    while (t < t1) {
        const double gap = nearestCurtainKm(glm::normalize(o + t * d)) - reachKm_;
        if (gap > settings_.stepKm) {
            t += gap;
            continue;
        }
        const double h = std::min(settings_.stepKm, t1 - t);
        const glm::dvec3 p = o + (t + 0.5 * h) * d;
        // Every curtain within its reach emits: overlapping curtains add.
        for (size_t ci = 0; ci < curtains_.size(); ++ci) {
            const Nearest n = nearestOn(ci, glm::normalize(p));
            if (n.distanceKm > reachKm_)
                continue;
            const ReferenceCurtain& c = curtains_[ci];
            const double flux = c.peakFlux * profile(c, n.sKm, n.uKm);
            if (flux > 0.0)
                sum += flux * h * emissionRgbPerKm(glm::length(p) - R, c.energyKeV);
        }
        t += h;
    }
    return sum;
}

// shadeRay of shaders/render/composite.glsl in double: the layers from the shared module
// render/layers.glsl, composited front to back in the same order.
glm::dvec3 ReferenceModel::radiance(glm::dvec3 o, glm::dvec3 direction) const
{
    using scene::Component;
    const glm::dvec3 d = glm::normalize(direction);
    const double R = scene_.planet.radiusKm;
    const bool hasAtmosphere = scene_.has(Component::Atmosphere), hasAurora = scene_.has(Component::Aurora);
    const scene::Atmosphere& air = scene_.atmosphere;
    const f64::RayLayers layers =
        f64::rayLayers(o, d, R, glm::length(o) - R, hasAtmosphere ? air.topKm : 0.0,
                       hasAurora ? scene_.aurora.bottomKm : 0.0, hasAurora ? scene_.aurora.topKm : 0.0);
    const bool hasPlanet = scene_.has(Component::Planet);
    if (hasPlanet && layers.insideGround)
        return glm::dvec3(0.0);
    glm::dvec3 radiance(0.0);
    glm::dvec3 transmittance(1.0);
    if (hasAtmosphere && layers.atmosphere.x < layers.atmosphere.y) {
        const double airmass = exactAirmass(o, d, layers.atmosphere.x, layers.atmosphere.y, air.scaleHeightKm, R);
        transmittance = glm::exp(-air.extinctionPerKm * airmass);
        radiance += air.skyGlow * (1.0 - transmittance);
    }
    if (hasAurora)
        for (const glm::dvec2 seg : {layers.auroraNear, layers.auroraFar})
            if (seg.x < seg.y)
                radiance += auroraSegment(o, d, seg.x, seg.y) *
                            (f64::behindAtmosphere(seg, layers.atmosphere) ? transmittance : glm::dvec3(1.0));
    if (hasPlanet && layers.groundT >= 0.0)
        radiance += scene_.planet.surfaceRadiance * transmittance;
    return radiance;
}

} // namespace aurorawall::render
