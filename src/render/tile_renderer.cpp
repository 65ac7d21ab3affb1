#include "render/tile_renderer.h"

#include "render/fragment_shader.h"
#include "render/scene_uniforms.h"

namespace aurorawall::render {

TileRenderer::TileRenderer(const scene::Scene& scene, const std::string& shaderDir)
    : scene_(scene),
      program_(gl::Program::graphics(gl::fullScreenTriangleVertexShader(), fragmentShaderSource(scene, shaderDir)))
{
    if (scene.has(scene::Component::Aurora)) {
        auroraTables_ = std::make_unique<AuroraTables>(scene.aurora);
        precomputationLog_.push_back(auroraTables_->summary());
        if (scene.has(scene::Component::FluidDetail)) {
            curtainDetail_ = std::make_unique<CurtainDetail>(scene.aurora.detail);
            precomputationLog_.push_back(curtainDetail_->summary());
        }
        curtainField_ = std::make_unique<CurtainField>(scene, curtainDetail_.get());
    }
    if (scene.has(scene::Component::PlanetTexture)) {
        nightLights_ = std::make_unique<NightLights>(scene.planet);
        precomputationLog_.push_back(nightLights_->summary());
    }
}

void TileRenderer::setFrame(const cluster::FrameState& frame)
{
    // Wall frame (x right, y up, z toward the viewer) -> camera axes in the planet frame.
    wallToPlanet_ = glm::dmat3(frame.cameraRight, frame.cameraUp, frame.cameraBack);
    applySceneUniforms(program_, scene_, frame);
    if (curtainField_)
        curtainField_->update(frame.timeS);
}

std::string TileRenderer::frameLog() const { return curtainField_ ? curtainField_->summary() : std::string(); }

void TileRenderer::renderTile(const wall::TileRays& rays, gl::FloatTarget& target,
                              const gl::FullScreenTriangle& triangle)
{
    program_.set("uRayOrigin", glm::vec3(wallToPlanet_ * rays.originDir));
    program_.set("uRayStepRight", glm::vec3(wallToPlanet_ * rays.stepRight));
    program_.set("uRayStepDown", glm::vec3(wallToPlanet_ * rays.stepDown));
    program_.set("uPixelOffset", glm::vec2(rays.pixelOffset)); // integers: exact in float below 2^24
    program_.set("uTileHeight", target.height());
    // Angular size of one pixel at the canvas origin, for drawing point-like stars.
    program_.set("uPixelAngle", static_cast<float>(glm::length(rays.stepRight) / glm::length(rays.originDir)));
    // Texture bindings belong to the current context: bind every time.
    if (auroraTables_)
        auroraTables_->bind(program_);
    if (curtainDetail_)
        curtainDetail_->bind(program_);
    if (curtainField_)
        curtainField_->bind(program_);
    if (nightLights_)
        nightLights_->bind(program_);
    target.bind();
    program_.use();
    triangle.draw();
}

} // namespace aurorawall::render
