#include "components/aurora/curtain_field.h"

#include "components/aurora/physics/curtain_geometry.h"
#include "components/aurora/physics/footprint_map.h"
#include "common/constants.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace aurorawall::components::aurora {

namespace {


// The map's cap: centred on the mean direction of all curtain points, wide enough to hold every
// point and the emitting band around it (reach) with room for the map's margin.
physics::FootprintMapSpec capAround(const std::vector<physics::CurtainPolyline>& curtains, double extraKm,
                                   double planetRadiusKm, int size)
{
    glm::dvec3 sum(0.0);
    for (const auto& c : curtains)
        for (const glm::dvec3& p : c.points)
            sum += p;
    const glm::dvec3 centre = glm::length(sum) > 0.0 ? glm::normalize(sum) : glm::dvec3(0, 0, 1);
    double radius = 0.0;
    for (const auto& c : curtains)
        for (const glm::dvec3& p : c.points)
            radius = std::max(radius, std::acos(std::clamp(glm::dot(p, centre), -1.0, 1.0)));
    physics::FootprintMapSpec spec;
    const glm::dvec2 latLon = physics::latLonFromUnit(centre);
    spec.centreLatitudeDeg = latLon.x;
    spec.centreLongitudeDeg = latLon.y;
    spec.angularRadiusDeg = std::min(90.0, (radius + extraKm / planetRadiusKm) / kDegree + 0.5);
    spec.size = size;
    return spec;
}

// Uploads into the texture kept from the last frame when its size is the same, else into a new one.
void uploadInto(std::unique_ptr<gl::Texture>& texture, int width, int height, const std::vector<float>& texels)
{
    if (!texture || texture->width() != width || texture->height() != height)
        texture = std::make_unique<gl::Texture>(
            gl::Texture::create2D(width, height, gl::TexelFormat::RGBA32F, gl::Filter::Nearest, gl::Wrap::Clamp));
    texture->upload(texels);
}

} // namespace

CurtainField::CurtainField(const CurtainModel& model) : model_(model)
{
    reachKm_ = static_cast<float>(model.reachKm());
    state_.resize(model.settings().curtains.size());
    detailUniform_.resize(state_.size());
}

void CurtainField::update(double timeS)
{
    const auto start = std::chrono::steady_clock::now();
    const std::vector<CurtainState> states = model_.statesAt(timeS);
    // The polylines and the map are functions of the control points alone: rebuilt only when those
    // differ (exactly) from the last build's, e.g. not while every curtain holds still.
    std::vector<std::vector<glm::dvec2>> controlPoints;
    for (const CurtainState& s : states)
        controlPoints.push_back(s.controlPointsLatLonDeg);
    const bool rebuilt = !footprint_ || controlPoints != controlPoints_;
    if (rebuilt) {
        controlPoints_ = std::move(controlPoints);
        rebuild(states);
    }
    for (size_t i = 0; i < states.size(); ++i) {
        const CurtainState& s = states[i];
        state_[i] = glm::vec4(s.energyFluxErgPerCm2S, s.energyKeV, static_cast<float>(pointCounts_[i]), 0.0f);
        detailUniform_[i] = glm::vec4(s.detailOffsetKm, s.detailPhase, model_.lateralScale(i), 0.0f);
    }

    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    char text[240];
    std::snprintf(text, sizeof text,
                  "curtains: %zu, %zu points, footprint map %d^2 (radius %.1f deg, margin %.2f km), %s: %.1f ms",
                  states.size(), pointTotal_, static_cast<int>(size_), angularRadiusDeg_, marginKm_,
                  rebuilt ? "rebuilt" : "unchanged", ms);
    summary_ = text;
}

void CurtainField::rebuild(const std::vector<CurtainState>& states)
{
    const Settings& aurora = model_.settings();
    const double R = model_.planetRadiusKm();
    std::vector<physics::CurtainPolyline> polylines;
    size_t widest = 1;
    pointCounts_.clear();
    pointTotal_ = 0;
    for (const CurtainState& s : states) {
        polylines.push_back(model_.footprint(s));
        const size_t n = polylines.back().points.size();
        widest = std::max(widest, n);
        pointCounts_.push_back(n);
        pointTotal_ += n;
    }

    // One row per curtain: unit vector and arclength (km); rows padded with their last point.
    const size_t rows = std::max<size_t>(polylines.size(), 1);
    std::vector<float> texels(4 * widest * rows, 0.0f);
    for (size_t c = 0; c < polylines.size(); ++c)
        for (size_t k = 0; k < widest; ++k) {
            const size_t j = std::min(k, polylines[c].points.size() - 1);
            const glm::dvec3& p = polylines[c].points[j];
            float* t = &texels[4 * (c * widest + k)];
            t[0] = static_cast<float>(p.x);
            t[1] = static_cast<float>(p.y);
            t[2] = static_cast<float>(p.z);
            t[3] = static_cast<float>(polylines[c].arclengthKm[j]);
        }
    uploadInto(polylines_, static_cast<int>(widest), static_cast<int>(rows), texels);

    // The cap must hold every curtain's emitting band plus the map's margin (at most a few texels).
    const double extraKm = reachKm_ + 2.0 * aurora.polylineSpacingKm + 100.0;
    physics::FootprintMapSpec spec = capAround(polylines, extraKm, R, aurora.footprintMapSize);
    spec.reachKm = reachKm_;
    const physics::FootprintMap map = physics::buildFootprintMap(polylines, spec, R);
    uploadInto(footprint_, map.spec.size, map.spec.size, map.texels);
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
    }
    program.set("uCurtainReachKm", reachKm_);
    program.set("uFootprintCentre", centre_);
    program.set("uFootprintEast", east_);
    program.set("uFootprintAngularRadius", angularRadius_);
    program.set("uFootprintSize", size_);
    program.set("uFootprintMarginKm", marginKm_);
}

} // namespace aurorawall::components::aurora
