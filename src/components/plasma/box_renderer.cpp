#include "components/plasma/box_renderer.h"

#include "common/data_dir.h"
#include "common/formatted.h"
#include "gl/functions.h"
#include "gl/shader_program.h"
#include "io/table_cache.h"
#include "physics/colour.h"
#include "physics/emission_lines.h"
#include "scene/scene.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace aurorawall::components::plasma {

BoxRenderer::BoxRenderer(const Settings& plasma, const scene::Scene& scene, double planetRadiusKm)
    : PlasmaDetail(plasma, scene), box_(plasma.kind == Settings::Kind::Box), settings_(plasma),
      reachRadiusKm_(scene.reachRadiusKm()),
      boxFrames_(gl::Texture::create3D(1, 1, 1, gl::TexelFormat::R32F, gl::Filter::Linear, gl::Wrap::Repeat))
{
    boxSummary_ = PlasmaDetail::precomputationLog();
    if (!box_) {
        boxFrames_.upload({0.0f});
        return;
    }
    const auto start = std::chrono::steady_clock::now();
    const BoxFramesSpec spec = boxFramesSpec(plasma);
    BoxFrames f;
    std::string outcome;
    if (plasma.device == Settings::Device::Gpu) {
        const simulation::PeriodicGrid grid = boxGrid(spec);
        const simulation::Particles electrons = boxElectrons(spec);
        f = {spec.cells, 1, boxFrameDensity(spec, grid, electrons)};
        liveBox_ = std::make_unique<LivePic>(
            grid, electrons, glm::dvec3(0.0, 0.0, spec.magneticFieldT), spec.timeStepS,
            [spec](const simulation::PeriodicGrid& g, const simulation::Particles& e) {
                return boxFrameDensity(spec, g, e);
            },
            common::dataDirectory() + "/shaders");
        outcome = "live on the GPU";
    } else {
        CachedBoxFrames cached = cachedBoxFrames(spec, io::defaultCacheDirectory());
        f = std::move(cached.frames);
        outcome = cached.outcome;
    }
    boxFrames_ = gl::Texture::create3D(f.cells, f.cells, f.cells * f.frames, gl::TexelFormat::R32F, gl::Filter::Linear,
                                       gl::Wrap::Repeat);
    boxFrames_.upload(f.density);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

    centreKm_ =
        scene::planetPoint(plasma.boxLatitudeDeg, plasma.boxLongitudeDeg, planetRadiusKm + plasma.boxAltitudeKm);
    const scene::LocalFrame local = scene::localFrame(plasma.boxLatitudeDeg, plasma.boxLongitudeDeg);
    axes_ = glm::dmat3(local.east, local.north, local.up);
    const aurorawall::physics::LineInfo& line = aurorawall::physics::lineInfo(aurorawall::physics::EmissionLine::Green5577);
    const glm::dvec3 green = aurorawall::physics::lineLinearSrgbPerRayleigh(line.wavelengthNm, line.cieXyz);
    rgbPerDensityKm_ = glm::vec3(green * plasma.boxRayleighPerKm);

    float peak = 0.0f;
    for (float n : f.density)
        peak = std::max(peak, n);
    boxSummary_ += common::formatted(
                  "; plasma box: %d^3 cells, %d frames of %d steps, beams %.3g m/s, peak n/n0 %.2f, "
                  "%s: %.0f ms",
                  f.cells, spec.frames, spec.stepsPerFrame, boxBeamSpeed(spec), peak, outcome.c_str(), ms);
}

void BoxRenderer::setFrame(gl::Program& program, const cluster::FrameState& frame)
{
    PlasmaDetail::setFrame(program, frame);
    double position = 0.0;
    if (liveBox_) {
        liveBox_->showStep(boxStep(settings_, frame.timeS),
                           [this](const std::vector<float>& density) { boxFrames_.upload(density); });
    } else if (box_) {
        position = boxFramePosition(settings_, frame.timeS);
    }
    program.set("uPlasmaBoxCentreFromRayStart", glm::vec3(centreKm_ - cluster::rayStart(frame, reachRadiusKm_).pointKm));
    program.set("uPlasmaBoxAxes", glm::mat3(axes_));
    const float steps = box_ ? static_cast<float>(settings_.boxStepsPerCell * settings_.boxCells) : 0.0f;
    const float frames = box_ && !liveBox_ ? static_cast<float>(settings_.boxFrames) : 1.0f;
    program.set("uPlasmaBox",
                glm::vec4(static_cast<float>(settings_.boxSideKm), steps, static_cast<float>(position), frames));
    program.set("uPlasmaBoxCells", box_ ? settings_.boxCells : 1);
    program.set("uPlasmaBoxRgb", rgbPerDensityKm_);
}

void BoxRenderer::bind(gl::Program& program) const
{
    PlasmaDetail::bind(program);
    program.bindTexture("uPlasmaBoxFrames", 9, boxFrames_.id());
}

} // namespace aurorawall::components::plasma
