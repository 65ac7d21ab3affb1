#include "components/aurora/curtain_field.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

namespace aurorawall::components::aurora {

namespace {

// The texture kept from the last frame when its size is the same, else a new one (RGBA32F).
gl::Texture& sized(std::unique_ptr<gl::Texture>& texture, int width, int height)
{
    if (!texture || texture->width() != width || texture->height() != height)
        texture = std::make_unique<gl::Texture>(
            gl::Texture::create2D(width, height, gl::TexelFormat::RGBA32F, gl::Filter::Nearest, gl::Wrap::Clamp));
    return *texture;
}

} // namespace

glm::vec4 curtainStateUniform(const CurtainModel& model, size_t i, const CurtainState& s, size_t pointCount)
{
    return glm::vec4(s.energyFluxErgPerCm2S, s.energyKeV, static_cast<float>(pointCount),
                     static_cast<float>(model.reachKm(i, s.detailPhase)));
}

glm::vec4 curtainDetailUniform(const CurtainModel& model, size_t i, const CurtainState& s)
{
    return glm::vec4(s.detailOffsetKm, s.detailPhase, model.lateralScale(i), 0.0f);
}

CurtainField::CurtainField(const CurtainModel& model, MapBuilder builder, const std::string& shaderDir)
    : model_(model), ahead_(model, builder),
      gpuMap_(builder == MapBuilder::Gpu ? std::make_unique<FootprintMapGpu>(shaderDir) : nullptr)
{
    state_.resize(model.settings().curtains.size());
    detailUniform_.resize(state_.size());
}

void CurtainField::update(double timeS, double nextTimeS)
{
    const auto start = std::chrono::steady_clock::now();
    const std::vector<CurtainState> states = model_.statesAt(timeS);
    // The polylines and the map are functions of the control points alone: rebuilt only when those
    // differ (exactly) from the last build's, e.g. not while every curtain holds still.
    const ControlPoints controlPoints = controlPointsOf(states);
    std::optional<CurtainBuild> ahead = ahead_.take(controlPoints);
    const bool rebuilt = !footprint_ || controlPoints != controlPoints_;
    if (rebuilt) {
        ++rebuilds_;
        if (ahead) {
            ++rebuildsBuiltAhead_;
            upload(*ahead);
        } else {
            upload(buildCurtains(model_, states, gpuMap_ ? MapBuilder::Gpu : MapBuilder::Cpu));
        }
    }
    // The march skips by the largest reach of the curtains that emit now (their detail's spread at this
    // phase), not of all phases: nearer the curtains than the all-time largest reach it skips further.
    reachKm_ = 0.0f;
    for (size_t i = 0; i < states.size(); ++i) {
        const CurtainState& s = states[i];
        state_[i] = curtainStateUniform(model_, i, s, pointCounts_[i]);
        detailUniform_[i] = curtainDetailUniform(model_, i, s);
        if (state_[i].x > 0.0f)
            reachKm_ = std::max(reachKm_, state_[i].w);
    }
    buildAhead(nextTimeS);

    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    char text[280];
    std::snprintf(text, sizeof text,
                  "curtains: %zu, %zu points, footprint map %d^2 on the %s (radius %.1f deg, margin %.2f km), %s: "
                  "%.1f ms, built ahead: %zu of %zu rebuilds",
                  states.size(), pointTotal_, static_cast<int>(size_), gpuMap_ ? "GPU" : "CPU", angularRadiusDeg_,
                  marginKm_,
                  rebuilt ? "rebuilt" : "unchanged", ms, rebuildsBuiltAhead_, rebuilds_);
    summary_ = text;
}

std::vector<float> CurtainField::energiesKeV() const
{
    std::vector<float> energies;
    for (const glm::vec4& s : state_)
        energies.push_back(s.y);
    return energies;
}

void CurtainField::buildAhead(double nextTimeS)
{
    if (std::isnan(nextTimeS))
        return;
    std::vector<CurtainState> next = model_.statesAt(nextTimeS);
    if (controlPointsOf(next) != controlPoints_)
        ahead_.start(std::move(next));
}

void CurtainField::upload(const CurtainBuild& build)
{
    controlPoints_ = build.controlPoints;
    pointCounts_ = build.pointCounts;
    pointTotal_ = build.pointTotal;
    lengthsKm_ = build.lengthsKm;
    cornerSlopes_ = build.cornerSlopes;
    sized(polylines_, build.polylineWidth, build.polylineRows).upload(build.polylineTexels);
    // The GPU's map has its own frame (its margin holds the float allowance); the CPU's is uploaded
    // as built (a reference: its texels are 4 MiB at 512²).
    const physics::FootprintMap gpuFrame = gpuMap_ ? FootprintMapGpu::gpuFrame(build.map) : physics::FootprintMap{};
    const physics::FootprintMap& map = gpuMap_ ? gpuFrame : build.map;
    const int n = map.spec.size;
    if (gpuMap_)
        gpuMap_->build(map, *polylines_, pointCounts_, sized(footprint_, n, n));
    else
        sized(footprint_, n, n).upload(map.texels);
    centre_ = glm::vec3(map.centre);
    east_ = glm::vec3(map.east);
    angularRadius_ = static_cast<float>(map.angularRadius);
    angularRadiusDeg_ = map.spec.angularRadiusDeg;
    size_ = static_cast<float>(map.spec.size);
    marginKm_ = static_cast<float>(map.marginKm);
}

void CurtainField::bind(gl::Program& program) const
{
    program.bindTexture("uCurtainPolylines", 4, polylines_->id());
    program.bindTexture("uFootprintMap", 5, footprint_->id());
    program.set("uCurtainCount", static_cast<int>(state_.size()));
    if (!state_.empty()) {
        program.set("uCurtainState", state_);
        program.set("uCurtainDetail", detailUniform_);
        program.set("uCurtainLengthKm", lengthsKm_);
        program.set("uCurtainCornerSlope", cornerSlopes_);
    }
    program.set("uCurtainReachKm", reachKm_);
    program.set("uFootprintCentre", centre_);
    program.set("uFootprintEast", east_);
    program.set("uFootprintAngularRadius", angularRadius_);
    program.set("uFootprintSize", size_);
    program.set("uFootprintMarginKm", marginKm_);
}

} // namespace aurorawall::components::aurora
