#include "render/scene_uniforms.h"

#include <cmath>

namespace aurorawall::render {

namespace {
constexpr double kTwoPi = 6.28318530717958647692;
}

CurtainUniforms curtainUniforms(const scene::Scene& scene, double timeS)
{
    CurtainUniforms u;
    for (const scene::Curtain& c : scene.aurora.curtains) {
        u.ranges.emplace_back(static_cast<float>(u.points.size()), static_cast<float>(c.pointsLatLonDeg.size()));
        double arclengthKm = 0.0;
        glm::dvec3 previous{0.0};
        for (size_t i = 0; i < c.pointsLatLonDeg.size(); ++i) {
            const glm::dvec3 p = scene::planetPoint(c.pointsLatLonDeg[i].x, c.pointsLatLonDeg[i].y, 1.0);
            if (i > 0)
                arclengthKm += scene.planet.radiusKm *
                               std::atan2(glm::length(glm::cross(previous, p)), glm::dot(previous, p));
            u.points.emplace_back(glm::vec3(p), static_cast<float>(arclengthKm));
            previous = p;
        }
        u.shapes.emplace_back(c.energyFluxErgPerCm2S, 0.5 * c.thicknessKm, c.energyKeV, c.foldAmplitudeKm);
        // Folds travel along the curtain: phase = -2 pi drift t / wavelength, reduced in double.
        const double cycles = std::fmod(c.driftKmPerS * timeS / c.foldWavelengthKm, 1.0);
        const double phase = std::fmod(kTwoPi * (1.0 - cycles), kTwoPi);
        u.folds.emplace_back(kTwoPi / c.foldWavelengthKm, phase);
    }
    return u;
}

void applySceneUniforms(gl::Program& program, const scene::Scene& scene, const cluster::FrameState& frame)
{
    program.set("uCameraPositionKm", glm::vec3(frame.cameraPositionKm));
    const double cameraRadiusKm = glm::length(frame.cameraPositionKm);
    if (scene.has(scene::Component::Planet)) {
        program.set("uPlanetRadiusKm", static_cast<float>(scene.planet.radiusKm));
        program.set("uCameraAltitudeKm", static_cast<float>(cameraRadiusKm - scene.planet.radiusKm));
        program.set("uPlanetRadiance", glm::vec3(scene.planet.surfaceRadiance));
    }
    if (scene.has(scene::Component::Atmosphere)) {
        program.set("uAtmosphereTopKm", static_cast<float>(scene.atmosphere.topKm));
        program.set("uScaleHeightKm", static_cast<float>(scene.atmosphere.scaleHeightKm));
        program.set("uExtinctionPerKm", glm::vec3(scene.atmosphere.extinctionPerKm));
        program.set("uSkyGlow", glm::vec3(scene.atmosphere.skyGlow));
    }
    if (scene.has(scene::Component::Aurora)) {
        program.set("uAuroraBottomKm", static_cast<float>(scene.aurora.bottomKm));
        program.set("uAuroraTopKm", static_cast<float>(scene.aurora.topKm));
        program.set("uAuroraStepKm", static_cast<float>(scene.aurora.stepKm));
        const CurtainUniforms c = curtainUniforms(scene, frame.timeS);
        program.set("uCurtainCount", static_cast<int>(c.ranges.size()));
        if (!c.ranges.empty()) {
            program.set("uCurtainPoints", c.points);
            program.set("uCurtainRange", c.ranges);
            program.set("uCurtainShape", c.shapes);
            program.set("uCurtainFold", c.folds);
        }
    }
    if (scene.has(scene::Component::Stars)) {
        program.set("uStarDensity", static_cast<float>(scene.stars.density));
        program.set("uStarBrightness", static_cast<float>(scene.stars.brightness));
    }
}

} // namespace aurorawall::render
