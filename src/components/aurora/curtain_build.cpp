#include "components/aurora/curtain_build.h"

#include "components/aurora/physics/curtain_geometry.h"
#include "physics/constants.h"

#include <algorithm>
#include <cmath>

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
    spec.angularRadiusDeg = std::min(90.0, (radius + extraKm / planetRadiusKm) / aurorawall::physics::kDegree + 0.5);
    spec.size = size;
    return spec;
}

// tan(θ/2) of the largest turn θ between consecutive segments of the polyline as the shader sees it: the
// angle between the great circles' normals computed from the float points (segment_projection.glsl),
// which tilt by up to ~1e-7 R / (segment length) from the exact ones; plus 1e-4 for the GPU's own rounding.
double cornerSlope(const physics::CurtainPolyline& polyline)
{
    const auto normal = [&](size_t j) {
        const glm::vec3 a(polyline.points[j]), b(polyline.points[j + 1]);
        return glm::dvec3(glm::normalize(glm::cross(a, b - a)));
    };
    double largestTurn = 0.0;
    for (size_t j = 1; j + 1 < polyline.points.size(); ++j)
        largestTurn = std::max(largestTurn, std::acos(std::clamp(glm::dot(normal(j - 1), normal(j)), -1.0, 1.0)));
    return std::tan(0.5 * std::min(largestTurn, 3.0)) + 1.0e-4;
}

} // namespace

std::vector<float> polylineTexels(const std::vector<physics::CurtainPolyline>& polylines, int& width, int& rows)
{
    size_t widest = 1;
    for (const physics::CurtainPolyline& c : polylines)
        widest = std::max(widest, c.points.size());
    width = static_cast<int>(widest);
    rows = static_cast<int>(std::max<size_t>(polylines.size(), 1));
    std::vector<float> texels(4 * widest * size_t(rows), 0.0f);
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
    return texels;
}

ControlPoints controlPointsOf(const std::vector<CurtainState>& states)
{
    ControlPoints points;
    for (const CurtainState& s : states)
        points.push_back(s.controlPointsLatLonDeg);
    return points;
}

CurtainBuild buildCurtains(const CurtainModel& model, const std::vector<CurtainState>& states, MapBuilder builder)
{
    const Settings& aurora = model.settings();
    CurtainBuild build;
    build.controlPoints = controlPointsOf(states);
    std::vector<physics::CurtainPolyline>& polylines = build.polylines;
    for (const CurtainState& s : states) {
        polylines.push_back(model.footprint(s));
        build.pointCounts.push_back(polylines.back().points.size());
        build.pointTotal += polylines.back().points.size();
        build.lengthsKm.push_back(static_cast<float>(polylines.back().arclengthKm.back()));
        build.cornerSlopes.push_back(static_cast<float>(cornerSlope(polylines.back())));
    }
    build.polylineTexels = polylineTexels(polylines, build.polylineWidth, build.polylineRows);

    // The cap must hold every curtain's emitting band plus the map's margin (at most a few texels).
    // A march step reaches half its length beyond its midpoint, where the shader reads the map: the
    // map is exact, and names a second curtain, out to the reach plus half a step (the shader's float
    // uniforms, so the map is exact for those same values).
    const double reachKm = double(static_cast<float>(model.reachKm())) + 0.5 * double(static_cast<float>(aurora.stepKm));
    const double extraKm = reachKm + 2.0 * aurora.polylineSpacingKm + 100.0;
    physics::FootprintMapSpec spec = capAround(polylines, extraKm, model.planetRadiusKm(), aurora.footprintMapSize);
    spec.reachKm = reachKm;
    build.map = builder == MapBuilder::Cpu ? physics::buildFootprintMap(polylines, spec, model.planetRadiusKm())
                                           : physics::footprintMapFrame(polylines, spec, model.planetRadiusKm());
    return build;
}

} // namespace aurorawall::components::aurora
