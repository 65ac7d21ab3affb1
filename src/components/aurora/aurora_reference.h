#pragma once
// The aurora's part of the double-precision CPU reference: the emission shaders/components/aurora
// computes, without its approximations:
//   - the same curtain model (curtain_model.h): keyframes, dense polylines, lateral scale and reach;
//   - curtain coordinates (s, u) on EVERY curtain by exact projection on its segments (no
//     footprint map); each curtain emits within its own reach of its centre line and ends, and
//     overlapping curtains add (the shader sees the two nearest curtains at a point);
//   - emission: flux x profile(s, u) x the line emission of aurora::depositionRate,
//     aurora::lineYield and aurora::lineLinearSrgbPerRayleigh in double (no decibel tables); the
//     fluid profile from roles::sampleFlux in double with the normalization of curtain_profile.glsl;
//   - the emission integral by the midpoint rule with a fine fixed step wherever a curtain is
//     within reach, and exact jumps over the rest (the distance to the nearest curtain, less the
//     reach, is a distance along the ray that cannot reach an emitting point).
#include "components/aurora/curtain_model.h"
#include "components/roles/curtain_detail.h"
#include "scene/component.h"

#include <glm/glm.hpp>

#include <vector>

namespace aurorawall::components::aurora {

class AuroraReference : public scene::ReferenceShader {
public:
    // frames: the curtain detail frames when the scene lists a provider of the role, else
    // null; shape: their shape for the curtain model; stripWidthKm: their strip's width.
    AuroraReference(const Settings& aurora, double planetRadiusKm, double timeS, double stepKm,
                    const roles::FluxFrames* frames, std::optional<roles::DetailShape> shape,
                    double stripWidthKm);

    scene::f64::Ray shade(scene::f64::Ray ray) const override;

private:
    struct Curtain {
        std::vector<glm::dvec3> points;  // unit vectors of the dense polyline
        std::vector<double> arclengthKm; // along the polyline from points[0]
        double maxSegmentKm = 0.0;       // longest segment (great-circle km on the planet)
        CurtainState state;
        double lateralScale = 0.0;
        double reachKm = 0.0;
    };
    struct Nearest {
        double distanceKm = 1e300; // to the polyline, great-circle km on the planet
        double sKm = 0.0;          // along the curtain
        double uKm = 0.0;          // signed, across it
        double beyondEndKm = 0.0;  // along it beyond its nearer end (0 between its ends)
    };
    Nearest nearestOn(const Curtain& c, glm::dvec3 unit) const;
    double nearestCurtainKm(glm::dvec3 unit) const;
    double profile(const Curtain& c, double sKm, double uKm) const;
    glm::dvec3 emissionRgbPerKm(double altitudeKm, double energyKeV) const;
    glm::dvec3 segment(glm::dvec3 o, glm::dvec3 d, double t0, double t1) const;

    const Settings& aurora_;
    double planetRadiusKm_;
    double stepKm_;
    const roles::FluxFrames* frames_;
    double stripWidthKm_;
    std::optional<roles::DetailShape> shape_;
    std::optional<CurtainModel> model_;
    std::vector<Curtain> curtains_;
    glm::dvec3 lineRgb_[4];
};

} // namespace aurorawall::components::aurora
