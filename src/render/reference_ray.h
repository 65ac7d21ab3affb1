#pragma once
// A double-precision CPU reference of the renderer's model for single rays: the
// radiance shaders/render/composite.glsl and shaders/scene/aurora_curtains.glsl compute, without
// their approximations. Same model, exact evaluation:
//   - layers: the shared modules shaders/render/ray_sphere.glsl and layers.glsl compiled in double;
//   - curtains: the same keyframes (render/curtain_frames.h) sampled into the same dense polylines
//     (aurora::sampleCurtain); curtain coordinates (s, u) on EVERY curtain by exact projection on
//     its segments (no footprint map); each curtain emits within reachKm of its centre line, as the
//     shader's cut-off says (CurtainField's reach), and overlapping curtains add (the shader sees the
//     two nearest curtains at a point);
//   - emission: flux x profile(s, u) x the line emission of aurora::depositionRate, aurora::lineYield and
//     aurora::lineLinearSrgbPerRayleigh in double (no decibel tables); the fluid profile from
//     fluid::sampleFlux in double with the normalization of shaders/aurora/curtain_profile.glsl;
//   - the emission integral by the midpoint rule with a fine fixed step (default 0.05 km) wherever a
//     curtain is within reach, and exact jumps over the rest (the distance to the nearest curtain,
//     less the reach, is a distance along the ray that cannot reach an emitting point);
//   - lower atmosphere: transmittance and sky glow from atmosphere::exactAirmass (Gauss-Kronrod).
// Not modelled, so the scene must not list them: stars (a hash of float direction bits: a
// point-sampled texture, not a model to converge to), planet_texture (an image lookup) and sky.
#include "fluid/curtain_detail.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace aurorawall::render {

struct ReferenceSettings {
    double stepKm = 0.05; // midpoint-rule step where a curtain is within reach
};

// The frame's curtains, as the shader sees them, in double.
struct ReferenceCurtain {
    std::vector<glm::dvec3> points;  // unit vectors of the dense polyline
    std::vector<double> arclengthKm; // along the polyline from points[0]
    double maxSegmentKm = 0.0;       // longest segment (great-circle km on the planet)
    double peakFlux = 0.0;           // erg cm^-2 s^-1
    double energyKeV = 0.0;
    double detailOffsetKm = 0.0;
    double detailPhase = 0.0;
    double lateralScale = 0.0;       // simulation sigma / curtain sigma (fluid), else 1 / sigma
};

class ReferenceModel {
public:
    // The scene at animation time timeS. detail: the fluid frames when the scene lists
    // fluid_detail (fluid::simulateCurtainDetail(curtainDetailSpec(scene.aurora.detail)) or others
    // on the same strip), else null. Throws std::invalid_argument if the scene lists stars,
    // planet_texture or sky, or lists fluid_detail without frames.
    ReferenceModel(const scene::Scene& scene, double timeS, const fluid::FluxFrames* detail,
                   ReferenceSettings settings = {});

    // Radiance (linear sRGB, cd/m^2) arriving at `originKm` (planet frame) from direction `direction`
    // (any length), i.e. shadeRay(o, d).
    glm::dvec3 radiance(glm::dvec3 originKm, glm::dvec3 direction) const;

private:
    struct Nearest {
        int curtain = -1;
        double distanceKm = 1e300; // to the polyline, great-circle km on the planet
        double sKm = 0.0;          // along the curtain
        double uKm = 0.0;          // signed, across it
    };
    Nearest nearestOn(size_t curtain, glm::dvec3 unit) const;
    double nearestCurtainKm(glm::dvec3 unit) const;
    double profile(const ReferenceCurtain& c, double sKm, double uKm) const;
    glm::dvec3 emissionRgbPerKm(double altitudeKm, double energyKeV) const;
    glm::dvec3 auroraSegment(glm::dvec3 o, glm::dvec3 d, double t0, double t1) const;

    const scene::Scene& scene_;
    const fluid::FluxFrames* detail_;
    ReferenceSettings settings_;
    std::vector<ReferenceCurtain> curtains_;
    double reachKm_ = 0.0;
    double fluxWidthKm_ = 0.0;
    double peakScale_ = 1.0;
    glm::dvec3 lineRgb_[4];
};

} // namespace aurorawall::render
