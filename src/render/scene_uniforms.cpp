#include "render/scene_uniforms.h"

namespace aurorawall::render {

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
    if (scene.has(scene::Component::Sky)) {
        const scene::Sky& sky = scene.sky;
        program.set("uSkyTopKm", static_cast<float>(sky.topKm));
        program.set("uSkyViewSteps", sky.viewSteps);
        program.set("uSkyLightMethod", sky.nestedMarch ? 1 : 0); // SKY_LIGHT_NESTED_MARCH : SKY_LIGHT_CLOSED_FORM
        program.set("uSkyLightSteps", sky.lightSteps);
        program.set("uSkyLightCount", static_cast<int>(sky.lights.size()));
        for (size_t i = 0; i < sky.lights.size(); ++i) {
            const std::string index = "[" + std::to_string(i) + "]";
            program.set("uSkyLightDirection" + index, glm::vec3(sky.lights[i].direction));
            program.set("uSkyLightIlluminanceLux" + index, glm::vec3(sky.lights[i].illuminanceLux));
        }
    }
    if (scene.has(scene::Component::Aurora)) {
        program.set("uAuroraBottomKm", static_cast<float>(scene.aurora.bottomKm));
        program.set("uAuroraTopKm", static_cast<float>(scene.aurora.topKm));
        program.set("uAuroraStepKm", static_cast<float>(scene.aurora.stepKm));
        program.set("uSkipEmptySpace", scene.aurora.skipEmptySpace ? 1 : 0);
    }
    if (scene.has(scene::Component::Stars)) {
        program.set("uStarDensity", static_cast<float>(scene.stars.density));
        program.set("uStarBrightness", static_cast<float>(scene.stars.brightness));
    }
}

} // namespace aurorawall::render
