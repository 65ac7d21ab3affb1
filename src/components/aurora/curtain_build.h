#pragma once
// The CPU part of the curtain field's rebuild: each curtain's dense polyline (one texture row each)
// and the footprint map (src/components/aurora/physics/footprint_map.h). A pure function of the
// curtains' control points, with no GL, so that it can run on a worker thread ahead of the frame
// that needs it and give the same bytes as a build on the frame's own thread.
#include "components/aurora/curtain_model.h"
#include "components/aurora/physics/footprint_map.h"

#include <glm/glm.hpp>

#include <vector>

namespace aurorawall::components::aurora {

// Every curtain's control points (latitude, longitude in degrees), in the scene's order.
using ControlPoints = std::vector<std::vector<glm::dvec2>>;

ControlPoints controlPointsOf(const std::vector<CurtainState>& states);

struct CurtainBuild {
    ControlPoints controlPoints;     // the input
    std::vector<size_t> pointCounts; // per curtain: points of its polyline
    size_t pointTotal = 0;
    // RGBA32F, polylineWidth × polylineRows: per point its unit vector and arclength (km); rows
    // padded with their last point.
    int polylineWidth = 1, polylineRows = 1;
    std::vector<float> polylineTexels;
    physics::FootprintMap map;
};

// The polylines and the map of the curtains' states (only their control points are read).
CurtainBuild buildCurtains(const CurtainModel& model, const std::vector<CurtainState>& states);

} // namespace aurorawall::components::aurora
