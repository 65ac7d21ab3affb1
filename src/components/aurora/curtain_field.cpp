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
    const bool uploadedAhead = back_.holdsBuild && back_.controlPoints == controlPoints;
    std::optional<CurtainBuild> ahead = uploadedAhead ? std::nullopt : ahead_.take(controlPoints);
    const bool rebuilt = !front_.holdsBuild || controlPoints != front_.controlPoints;
    if (rebuilt) {
        ++rebuilds_;
        if (uploadedAhead) {
            ++rebuildsBuiltAhead_;
            ++rebuildsUploadedAhead_;
            std::swap(front_, back_);
        } else if (ahead) {
            ++rebuildsBuiltAhead_;
            upload(*ahead, front_);
        } else {
            upload(buildCurtains(model_, states, gpuMap_ ? MapBuilder::Gpu : MapBuilder::Cpu), front_);
        }
    }
    back_.holdsBuild = false; // swapped in, or a wrong prediction: its textures are rewritten before use
    // The march skips by the largest reach of the curtains that emit now (their detail's spread at this
    // phase), not of all phases: nearer the curtains than the all-time largest reach it skips further.
    reachKm_ = 0.0f;
    for (size_t i = 0; i < states.size(); ++i) {
        const CurtainState& s = states[i];
        state_[i] = curtainStateUniform(model_, i, s, front_.pointCounts[i]);
        detailUniform_[i] = curtainDetailUniform(model_, i, s);
        if (state_[i].x > 0.0f)
            reachKm_ = std::max(reachKm_, state_[i].w);
    }
    buildAhead(nextTimeS);

    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    char text[280];
    std::snprintf(text, sizeof text,
                  "curtains: %zu, %zu points, footprint map %d^2 on the %s (radius %.1f deg, margin %.2f km), %s: "
                  "%.1f ms, built ahead: %zu of %zu rebuilds, uploaded ahead: %zu",
                  states.size(), front_.pointTotal, static_cast<int>(front_.size), gpuMap_ ? "GPU" : "CPU",
                  front_.angularRadiusDeg, front_.marginKm, rebuilt ? "rebuilt" : "unchanged", ms, rebuildsBuiltAhead_,
                  rebuilds_, rebuildsUploadedAhead_);
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
    if (controlPointsOf(next) != front_.controlPoints)
        ahead_.start(std::move(next));
}

void CurtainField::uploadAhead()
{
    if (gpuMap_)
        return;
    if (std::optional<CurtainBuild> build = ahead_.takeStarted())
        upload(*build, back_);
}

void CurtainField::upload(const CurtainBuild& build, Uploaded& into)
{
    into.holdsBuild = true;
    into.controlPoints = build.controlPoints;
    into.pointCounts = build.pointCounts;
    into.pointTotal = build.pointTotal;
    into.lengthsKm = build.lengthsKm;
    into.cornerSlopes = build.cornerSlopes;
    sized(into.polylines, build.polylineWidth, build.polylineRows).upload(build.polylineTexels);
    // The GPU's map has its own frame (its margin holds the float allowance); the CPU's is uploaded
    // as built (a reference: its texels are 4 MiB at 512²).
    const physics::FootprintMap gpuFrame = gpuMap_ ? FootprintMapGpu::gpuFrame(build.map) : physics::FootprintMap{};
    const physics::FootprintMap& map = gpuMap_ ? gpuFrame : build.map;
    const int n = map.spec.size;
    if (gpuMap_)
        gpuMap_->build(map, *into.polylines, into.pointCounts, sized(into.footprint, n, n));
    else
        sized(into.footprint, n, n).upload(map.texels);
    into.centre = glm::vec3(map.centre);
    into.east = glm::vec3(map.east);
    into.angularRadius = static_cast<float>(map.angularRadius);
    into.angularRadiusDeg = map.spec.angularRadiusDeg;
    into.size = static_cast<float>(map.spec.size);
    into.marginKm = static_cast<float>(map.marginKm);
}

void CurtainField::bind(gl::Program& program) const
{
    program.bindTexture("uCurtainPolylines", 4, front_.polylines->id());
    program.bindTexture("uFootprintMap", 5, front_.footprint->id());
    program.set("uCurtainCount", static_cast<int>(state_.size()));
    if (!state_.empty()) {
        program.set("uCurtainState", state_);
        program.set("uCurtainDetail", detailUniform_);
        program.set("uCurtainLengthKm", front_.lengthsKm);
        program.set("uCurtainCornerSlope", front_.cornerSlopes);
    }
    program.set("uCurtainReachKm", reachKm_);
    program.set("uFootprintCentre", front_.centre);
    program.set("uFootprintEast", front_.east);
    program.set("uFootprintAngularRadius", front_.angularRadius);
    program.set("uFootprintSize", front_.size);
    program.set("uFootprintMarginKm", front_.marginKm);
}

} // namespace aurorawall::components::aurora
