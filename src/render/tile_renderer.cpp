#include "render/tile_renderer.h"

#include "gl/context.h"
#include "gl/functions.h"
#include "render/march_shader.h"

#include <chrono>
#include <stdexcept>

namespace aurorawall::render {

namespace {

gl::Program marchProgram(const scene::Scene& scene, const std::string& shaderDir, MarchStage stage,
                         CountWork countWork, PixelWork pixelWork)
{
    if (countWork == CountWork::Yes && stage != MarchStage::Compute)
        throw std::invalid_argument("TileRenderer: work is counted by the compute march only");
    gl::ShaderSource source = marchShaderSource(scene, shaderDir, stage);
    if (countWork == CountWork::Yes)
        source.defines.push_back("AURORAWALL_WORK_STATS");
    if (pixelWork == PixelWork::ShaderClock) {
        if (!gl::hasExtension("GL_ARB_shader_clock"))
            throw std::invalid_argument("TileRenderer: the GPU clock needs GL_ARB_shader_clock, which " +
                                        gl::currentRendererName() + " lacks");
        source.extensions.push_back("GL_ARB_shader_clock");
        source.defines.push_back("AURORAWALL_WORK_CLOCK");
    }
    if (pixelWork == PixelWork::TextureFetches)
        source.defines.push_back("AURORAWALL_WORK_FETCHES");
    if (stage == MarchStage::Compute)
        return gl::Program::compute(source);
    return gl::Program::graphics(gl::fullScreenTriangleVertexShader(), source);
}

// v (planet frame) split in double into its part across the unit `forward` (xyz) and along it (w).
glm::vec4 splitAlong(glm::dvec3 v, glm::dvec3 forward)
{
    const double along = glm::dot(v, forward);
    return glm::vec4(glm::vec3(v - along * forward), static_cast<float>(along));
}

} // namespace

TileRenderer::TileRenderer(const scene::Scene& scene, const std::string& shaderDir)
    : TileRenderer(scene, shaderDir, preferredMarchStage(gl::currentRendererName()))
{
}

TileRenderer::TileRenderer(const scene::Scene& scene, const std::string& shaderDir, MarchStage stage,
                           CountWork countWork, PixelWork pixelWork)
    : scene_(scene), stage_(stage), countWork_(countWork), pixelWork_(pixelWork),
      program_(marchProgram(scene, shaderDir, stage, countWork, pixelWork))
{
    // A component finds the GPU part of a role's provider made before it (registry order).
    const scene::FindRenderer find = [&](const std::string& role) -> scene::ComponentRenderer* {
        const scene::Component* provider = scene.provider(role);
        for (size_t i = 0; i < components_.size(); ++i)
            if (scene.components()[i] == provider)
                return components_[i].get();
        return nullptr;
    };
    for (const scene::Component* c : scene.components()) {
        components_.push_back(c->makeRenderer(scene, find));
        const std::string log = components_.back()->precomputationLog();
        if (!log.empty())
            precomputationLog_.push_back(log);
    }
}

void TileRenderer::setFrame(const cluster::FrameState& frame)
{
    // Wall frame (x right, y up, z toward the viewer) -> camera axes in the planet frame; the flat
    // wall's rays with the frame's zoom, the dome master's without (its field of view is its own).
    wallToPlanet_ = cluster::wallToPlanet(frame);
    domeToPlanet_ = glm::dmat3(frame.cameraRight, frame.cameraUp, frame.cameraBack);
    zoom_ = frame.zoom;
    const cluster::RayStart start = cluster::rayStart(frame, scene_.reachRadiusKm());
    viewForward_ = start.forward;
    program_.set("uRayStartKm", glm::vec3(start.pointKm));
    program_.set("uRayStartDistanceKm", static_cast<float>(start.distanceKm));
    program_.set("uViewForward", glm::vec3(start.forward));
    componentFrameMs_.clear();
    for (const auto& c : components_) {
        const auto start = std::chrono::steady_clock::now();
        c->setFrame(program_, frame);
        componentFrameMs_.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
}

void TileRenderer::whileDrawing()
{
    for (const auto& c : components_)
        c->whileDrawing();
}

std::string TileRenderer::frameLog() const
{
    std::string log;
    for (const auto& c : components_) {
        const std::string line = c->frameLog();
        if (!line.empty())
            log += (log.empty() ? "" : "; ") + line;
    }
    return log;
}

void TileRenderer::renderTile(const wall::TileRays& rays, gl::FloatTarget& target,
                              const gl::FullScreenTriangle& triangle)
{
    program_.set("uRayOrigin", glm::vec3(wallToPlanet_ * rays.originDir));
    program_.set("uRayStepRight", glm::vec3(wallToPlanet_ * rays.stepRight));
    program_.set("uRayStepDown", glm::vec3(wallToPlanet_ * rays.stepDown));
    program_.set("uRayOriginRight", glm::vec3(wallToPlanet_ * rays.originDirRight));
    program_.set("uRayOriginSplit", splitAlong(wallToPlanet_ * rays.originDir, viewForward_));
    program_.set("uRayStepRightSplit", splitAlong(wallToPlanet_ * rays.stepRight, viewForward_));
    program_.set("uRayStepDownSplit", splitAlong(wallToPlanet_ * rays.stepDown, viewForward_));
    program_.set("uRayOriginRightSplit", splitAlong(wallToPlanet_ * rays.originDirRight, viewForward_));
    program_.set("uSplitX", static_cast<float>(rays.splitPx));
    program_.set("uPixelOffset", glm::vec2(rays.pixelOffset)); // integers: exact in float below 2^24
    program_.set("uTileHeight", target.height());
    // Angular size of one pixel at the canvas origin (dome: at the image centre), for drawing point-like light sources.
    const glm::dvec3 zoomed(1.0 / zoom_, 1.0 / zoom_, 1.0); // the zoom's scaling in the wall frame
    const double pixelAngle = rays.dome ? rays.domeRadiansPerPx
                                        : glm::length(zoomed * rays.stepRight) / glm::length(zoomed * rays.originDir);
    program_.set("uPixelAngle", static_cast<float>(pixelAngle));
    program_.set("uDome", rays.dome ? 1 : 0);
    program_.set("uDomeCentre", glm::vec2(rays.domeCentrePx)); // whole or half pixels: exact in float
    program_.set("uDomeRadius", static_cast<float>(rays.domeRadiusPx));
    program_.set("uDomeRadiansPerPixel", static_cast<float>(rays.domeRadiansPerPx));
    program_.set("uDomeAxis", glm::vec3(domeToPlanet_ * rays.domeAxis));
    program_.set("uDomeRight", glm::vec3(domeToPlanet_ * rays.domeRight));
    program_.set("uDomeDown", glm::vec3(domeToPlanet_ * rays.domeDown));
    // Texture bindings belong to the current context: bind every time.
    for (const auto& c : components_)
        c->bind(program_);
    program_.use();
    if (stage_ == MarchStage::Fragment) {
        target.bind();
        triangle.draw();
        return;
    }
    program_.set("uTileSize", glm::ivec2(target.width(), target.height()));
    gl::glBindImageTexture(0, target.texture().id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    gl::glBindImageTexture(1, target.work().id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    if (countWork_ == CountWork::Yes) {
        if (!workCounts_ || workCounts_->width() != target.width() || workCounts_->height() != target.height())
            workCounts_ = std::make_unique<gl::Texture>(gl::Texture::create2D(
                target.width(), target.height(), gl::TexelFormat::RGBA32F, gl::Filter::Nearest, gl::Wrap::Clamp));
        gl::glBindImageTexture(2, workCounts_->id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    }
    // Workgroups of main.comp's local size, kWarpWidth x kWarpHeight pixels.
    gl::glDispatchCompute(GLuint((target.width() + kWarpWidth - 1) / kWarpWidth),
                          GLuint((target.height() + kWarpHeight - 1) / kWarpHeight), 1);
    // The image stores before whatever reads the target next: read-backs, blits, texture fetches and
    // uploads of exchanged bands.
    gl::glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                    GL_PIXEL_BUFFER_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

std::vector<float> TileRenderer::workCounts(glm::ivec2 size) const
{
    if (!workCounts_ || workCounts_->width() != size.x || workCounts_->height() != size.y)
        throw std::logic_error("TileRenderer::workCounts: no counts of a tile of that size");
    std::vector<float> counts(std::size_t(size.x) * std::size_t(size.y) * kWorkQuantities);
    gl::glGetTextureImage(workCounts_->id(), 0, GL_RGBA, GL_FLOAT, GLsizei(counts.size() * sizeof(float)), counts.data());
    return counts;
}

} // namespace aurorawall::render
