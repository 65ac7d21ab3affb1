#pragma once
// The float bound of the aurora's march (shaders/components/aurora) against the same march in double
// (ReferenceSettings::shaderSteps), at a pixel of a scene with curtain detail: a GL test's tolerance between
// the GPU's image and that march, derived from the unit round-off and the scene's data.
#include "components/atmosphere/atmosphere.h"
#include "components/aurora/aurora.h"
#include "components/aurora/aurora_march.h"
#include "components/aurora/curtain_model.h"
#include "components/aurora/physics/emission_table.h"
#include "components/roles/curtain_detail.h"
#include "physics/atmosphere/airmass.h"
#include "float_bounds.h"
#include "scene/ray_steps.h"
#include "scene/scene.h"

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace aurorawall::test {

// How far a float march can lie from the same march in double given the same data (ReferenceSettings::
// shaderSteps) at one pixel, to first order in u = 2^-24, with the GLSL allowances of float_bounds.h:
//  - the ray's own rounding (camera position, direction): rayRoundingBound through the march in double;
//  - each sample o + t d at |x| <= r = R + the aurora's top rounds its product and sum, dx <= 2 u r; its
//    altitude |x| - R (a dot product, a square root), dh <= dx + 12 u r; its footprint n = x / |x| (19 u)
//    and the float segment normal (10 u) are unit vectors whose dot product (3 u) gives the curtain
//    coordinate R asin(n·normal) to 32 u R, and asin (atan along) adds 8192 u of the largest reach:
//    dq <= dx + 32 u R + 8192 u reach (2.3e-2 km with substorm's 20 km reach);
//  - the sky's glow G (1 - T), at most the pixel: the closed-form airmass's float error (floatAirmassError,
//    heights up to the atmosphere's top), and 1 - T's cancellation, GLSL's exp error over 1 - e^-y, y the
//    smallest extinction times the airmass;
//  - the emission rows (linear between nodes dz apart): (dh + 2^-9 dz) x the march of |dE/dz| (the march in
//    double over rows holding that slope; a GPU rounds a filter weight to 8 bits of fraction);
//  - the closed forms' cancellation: a sub-step's integral is a difference of running integrals, each within
//    a few u of the column's whole integral: at most 64 sub-steps a step, 128 u of the crossing's (the
//    moment's difference moves a sub-step's mean position within the sub-step: not bounded here); the
//    exact pieces (sub_step_flux = "exact") also take the mass from the moments' difference times
//    (λ_b − λ_a)/Δq, at most 1 / cell (bilinearPiece), and the moments B reach Q times the column's
//    integral, Q / cell at most the table's entries: consecutive pieces share their B reads, whose errors
//    cancel but for the first and last of each run of shared reads, 4 values within 2 u Q each; a step
//    has at most 76 such runs (65 cell centres, 2 band edges, 4 reach circles, the strip's period, ...:
//    curtainEnergyExact), 608 u Q / cell of the crossing's;
//  - the flux: a step's curtain coordinates are found once, at its midpoint, so their error dq shifts the
//    closed-form integrals of the whole step: by at most dq x the march of |dF/du| + |dF/ds| (the march in
//    double over frames holding that slope: the same steps, emission and flux scale); the filter weights
//    between cells and frames, by 2^-9 x the march of the neighbouring cells' and frames' |F' - F|.
// A discrete choice the round-off flips (a sub-step count, a candidate curtain) changes a step by its
// discretization, which the reference's tolerance holds (tests/render/shader_steps_test.cpp).
struct AuroraFloatBound {
    double dh = 0.0, dq = 0.0; // km: dh with the filter weight's 2^-9 of a node spacing
    double relative = 0.0;     // of the pixel: the airmass's float error and the closed forms' cancellation
    double scaleHeightKm = 0.0, atmosphereTopKm = 0.0, extinctionPerKm = 0.0; // the smallest extinction
    // The aurora's march in double over emission rows of |dE/dz| (1/km), and over frames of |dF/du| + |dF/ds|
    // (1/km^2) and of the neighbouring cells' and frames' |F' - F| (1/km).
    std::unique_ptr<scene::ReferenceShader> emissionSlope, slope, steps;

    // The bound at the pixel of radiance `pixel` whose ray starts at o in direction d (without the ray's own
    // rounding).
    double at(glm::dvec3 pixel, glm::dvec3 o, glm::dvec3 d, double planetRadiusKm) const
    {
        scene::f64::Ray ray{};
        ray.origin = o;
        ray.direction = d;
        ray.groundT = -1.0;
        ray.end = 1e30;
        ray.transmittance = glm::dvec3(1.0); // at most 1: the marches below stand in front of the atmosphere
        ray = scene::f64::boundByGround(ray, planetRadiusKm, glm::length(o) - planetRadiusKm);
        const glm::dvec2 air = scene::f64::lowerShellSegment(ray, planetRadiusKm, atmosphereTopKm);
        double glow = 0.0;
        if (air.x < air.y) {
            const double y = extinctionPerKm * physics::atmosphere::findAirmassMethod(physics::atmosphere::kDefaultAirmassMethod)
                                                   ->float64(o, d, air.x, air.y, scaleHeightKm, planetRadiusKm);
            glow = glslExpError(y) / -std::expm1(-y);
        }
        const double flux = dq * glm::length(slope->shade(ray).radiance) + std::ldexp(glm::length(steps->shade(ray).radiance), -9);
        return (relative + glow) * glm::length(pixel) + dh * glm::length(emissionSlope->shade(ray).radiance) + flux;
    }
};

// Each emission row's node replaced by the largest |E' - E| / dz of its neighbours (per channel): linear
// between nodes, that bounds |dE/dz| on either segment.
inline void rowSlopes(std::vector<float>& rows, int nodes, double nodeSpacingKm)
{
    const std::vector<float> e = rows;
    for (size_t row = 0; row < rows.size() / (4 * size_t(nodes)); ++row)
        for (size_t k = 0; k < size_t(nodes); ++k)
            for (size_t c = 0; c < 4; ++c) {
                const size_t i = 4 * (row * nodes + k) + c;
                double step = 0.0;
                if (k > 0)
                    step = std::abs(e[i] - e[i - 4]);
                if (k + 1 < size_t(nodes))
                    step = std::max(step, double(std::abs(e[i + 4] - e[i])));
                rows[i] = float(step / nodeSpacingKm);
            }
}

// Frames holding, at each cell, the largest |F' - F| of its neighbours across, along (scaled by `along`
// and `across`: 1 / cell km for slopes) and, with `frames`, in the neighbouring frames (periodic cells).
inline components::roles::FluxFrames neighbourSteps(const components::roles::FluxFrames& f, double along, double across, bool frames)
{
    components::roles::FluxFrames out = f;
    for (int k = 0; k < f.frames; ++k)
        for (int iy = 0; iy < f.ny; ++iy)
            for (int ix = 0; ix < f.nx; ++ix) {
                const double F = f.at(k, ix, iy);
                double alongStep = 0.0, acrossStep = 0.0, frameStep = 0.0;
                for (int side : {-1, 1}) {
                    alongStep = std::max(alongStep, std::abs(f.at(k, (ix + side + f.nx) % f.nx, iy) - F));
                    acrossStep = std::max(acrossStep, std::abs(f.at(k, ix, (iy + side + f.ny) % f.ny) - F));
                    if (frames && k + side >= 0 && k + side < f.frames)
                        frameStep = std::max(frameStep, std::abs(f.at(k + side, ix, iy) - F));
                }
                out.flux[(size_t(k) * f.ny + iy) * f.nx + ix] = float(along * alongStep + across * acrossStep + frameStep);
            }
    return out;
}

inline AuroraFloatBound auroraFloatBound(const scene::Scene& s, const components::roles::FluxFrames& frames, double timeS)
{
    const auto& aurora = s.settings<components::aurora::Settings>();
    const double u = kUnitRoundoff, R = s.planetRadiusKm, r = R + aurora.topKm;
    const components::roles::CurtainDetailProvider& provider = *components::roles::curtainDetailProvider(s);
    const components::roles::DetailShape shape = provider.referenceShape(s, frames);
    const components::aurora::CurtainModel model(aurora, R, &shape);
    double lateralScale = 0.0;
    for (size_t i = 0; i < aurora.curtains.size(); ++i)
        lateralScale = std::max(lateralScale, model.lateralScale(i));
    const auto& atmosphere = s.settings<components::atmosphere::Settings>();
    AuroraFloatBound b;
    const double dx = 2.0 * u * r, dz = aurora.tableAltitudeStepKm / components::aurora::physics::kEmissionSubdivisions;
    b.dq = dx + 32.0 * u * R + kGlslInverseTrigError * model.reachKm();
    b.dh = dx + 12.0 * u * r + std::ldexp(dz, -9);
    b.scaleHeightKm = atmosphere.scaleHeightKm;
    b.atmosphereTopKm = atmosphere.topKm;
    b.extinctionPerKm = std::min({atmosphere.extinctionPerKm.x, atmosphere.extinctionPerKm.y, atmosphere.extinctionPerKm.z});
    const double entries = std::max(frames.nx, frames.ny) + 1.0;
    b.relative = floatAirmassError(atmosphere.topKm / atmosphere.scaleHeightKm) + 128.0 * u +
                 (aurora.exactSubSteps ? 608.0 * u * entries : 0.0);
    // Slopes per curtain km: a cell along is texelKmX, one across texelKmY simulation km, lateralScale of them per km.
    const components::roles::FluxFrames slopes =
        neighbourSteps(frames, 1.0 / frames.texelKmX, lateralScale / frames.texelKmY, false);
    const components::roles::FluxFrames steps = neighbourSteps(frames, 1.0, 1.0, true);
    const double width = provider.stripWidthKm(s);
    b.emissionSlope = components::aurora::makeAuroraMarch(aurora, R, timeS, &frames, shape, width, rowSlopes);
    b.slope = components::aurora::makeAuroraMarch(aurora, R, timeS, &slopes, shape, width);
    b.steps = components::aurora::makeAuroraMarch(aurora, R, timeS, &steps, shape, width);
    return b;
}

// The GPU's pixels against the march in double (ReferenceSettings::shaderSteps) at the same pixels: each
// within its float bound (auroraFloatBound, plus the ray's own rounding), and against the fine CPU
// reference within that bound plus the reference's discretization, `discretization` of its radiance.
// Returns the largest |GPU − march| / bound and bound / |march|, and the bound's dh and dq, for the test's report.
struct FloatBoundCheck {
    double largestShare = 0.0;
    double largestBound = 0.0;
    double dh = 0.0, dq = 0.0;
};

inline FloatBoundCheck expectWithinFloatBound(const scene::Scene& s, const components::roles::FluxFrames& frames,
                                              const render::ReferenceModel& march, const accuracy::SceneView& view,
                                              const std::vector<glm::ivec2>& pixels, const std::vector<glm::dvec3>& gpu,
                                              const std::vector<glm::dvec3>& marched,
                                              const std::vector<glm::dvec3>& reference, double discretization)
{
    const AuroraFloatBound bound = auroraFloatBound(s, frames, view.frame.timeS);
    FloatBoundCheck check;
    check.dh = bound.dh;
    check.dq = bound.dq;
    for (size_t i = 0; i < pixels.size(); ++i) {
        const glm::ivec2 p = pixels[i];
        const glm::dvec3 o = view.frame.cameraPositionKm, d = accuracy::pixelDirection(view, p.x, p.y);
        const double limit = bound.at(marched[i], o, d, s.planetRadiusKm) + rayRoundingBound(march, view, p.x, p.y);
        const double difference = glm::length(gpu[i] - marched[i]);
        check.largestShare = std::max(check.largestShare, difference / limit);
        check.largestBound = std::max(check.largestBound, limit / glm::length(marched[i]));
        EXPECT_LT(difference, limit) << "pixel " << p.x << ", " << p.y;
        EXPECT_LT(glm::length(gpu[i] - reference[i]), limit + discretization * glm::length(reference[i]))
            << "pixel " << p.x << ", " << p.y;
    }
    return check;
}

} // namespace aurorawall::test
