#pragma once
// An airglow layer's column along a ray, for the airglow tests and the cost table: the shared
// shader modules in float (as the GPU evaluates them) and an independent fine march in double.
#include "common/glsl.h"
#include "components/airglow/airglow.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

// A named namespace: not every function of the modules is used.
namespace aurorawall::airglow_columns::f32 {
AURORAWALL_GLSL_PRECISION(float)
#include "render/ray_sphere.glsl"
#include "physics/constants.glsl"
#include "physics/atmosphere/airmass_common.glsl"
#include "physics/atmosphere/airmass_chapman.glsl"
#include "components/airglow/airglow_layer.glsl"
} // namespace aurorawall::airglow_columns::f32

namespace aurorawall::airglow_columns {

using components::airglow::LayerProfile;

inline constexpr double kPlanetRadiusKm = 6371.0;
inline constexpr double kTopScaleHeights = 40.0; // AIRGLOW_TOP_SCALE_HEIGHTS of airglow.glsl

// Where a ray from o along d (unit) meets the ground: 0 from below it, 1e30 if never.
inline double groundDistance(glm::dvec3 o, glm::dvec3 d)
{
    const double R = kPlanetRadiusKm;
    const double b = glm::dot(o, d), c = glm::dot(o, o) - R * R, disc = b * b - c;
    if (c < 0.0)
        return 0.0;
    if (disc < 0.0)
        return 1e30;
    const double t = -b - std::sqrt(disc);
    return t > 0.0 ? t : 1e30;
}

// The layer's shell parts of the ray, in float as the shader finds them.
inline f32::ShellSegments shellParts(const LayerProfile& p, glm::dvec3 o, glm::dvec3 d)
{
    const double R = kPlanetRadiusKm, altitude = glm::length(o) - R;
    const double base = p.baseKm, top = base + kTopScaleHeights * p.upperScaleHeightKm;
    return f32::rayShell(glm::vec3(o), glm::vec3(d), float(R + base), float(altitude - base), float(R + top),
                         float(altitude - top), float(groundDistance(o, d)));
}

// The column as the shader computes it: the layer's shell parts in float, each in closed form.
inline double closedFormColumn(const LayerProfile& p, glm::dvec3 o, glm::dvec3 d)
{
    const glm::vec3 of(o), df(d);
    const glm::vec4 l(p.baseKm, p.upperScaleHeightKm, p.lowerScaleHeightKm, p.rayleighPerKm);
    const f32::ShellSegments shell = shellParts(p, o, d);
    double sum = 0.0;
    for (const glm::vec2 part : {shell.first, shell.second})
        if (part.x < part.y)
            sum += f32::airglowColumn(of, df, part.x, part.y, l, float(kPlanetRadiusKm + p.baseKm));
    return sum;
}

// The column by the midpoint rule with step h (km) over the part of the ray below the layer's top,
// of the volume emission rate in double.
inline double marchedColumn(const LayerProfile& p, glm::dvec3 o, glm::dvec3 d, double h)
{
    const double R = kPlanetRadiusKm;
    const double rTop = R + p.baseKm + kTopScaleHeights * p.upperScaleHeightKm;
    const double b = glm::dot(o, d), c = glm::dot(o, o) - rTop * rTop, disc = b * b - c;
    if (disc < 0.0)
        return 0.0;
    const double t0 = std::max(0.0, -b - std::sqrt(disc));
    const double t1 = std::min(-b + std::sqrt(disc), groundDistance(o, d));
    double sum = 0.0;
    for (double t = t0; t < t1; t += h) {
        const double step = std::min(h, t1 - t);
        sum += step * components::airglow::volumeEmission(p, glm::length(o + (t + 0.5 * step) * d) - R);
    }
    return sum;
}

// A ray of the closed form's test and cost table: its origin's altitude (km), origin and direction (unit).
struct Ray {
    double altitude;
    glm::dvec3 o, d;
};

// The rays for one layer: from the ground, just above it, inside the layers, at the peak, from orbit and
// far in space, each in 12 random directions (drawn from `random`) and tangent to the sphere through the
// peak and through the base, where it exists.
inline std::vector<Ray> layerRays(const components::airglow::Layer& layer, std::mt19937& random)
{
    const double R = kPlanetRadiusKm;
    const LayerProfile p = components::airglow::layerProfile(layer);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    std::vector<Ray> rays;
    for (double altitude : {0.0, 0.001, 50.0, layer.peakKm, 400.0, 36000.0}) {
        const glm::dvec3 o(0.0, 0.0, R + altitude);
        for (int i = 0; i < 12; ++i)
            rays.push_back({altitude, o, glm::normalize(glm::dvec3(uniform(random), uniform(random), uniform(random)))});
        for (double h : {layer.peakKm, p.baseKm + 0.01})
            if (altitude > h) {
                const double s = (R + h) / (R + altitude);
                rays.push_back({altitude, o, {s, 0.0, -std::sqrt(1.0 - s * s)}});
            }
    }
    return rays;
}

} // namespace aurorawall::airglow_columns
