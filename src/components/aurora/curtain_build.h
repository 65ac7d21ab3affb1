#pragma once
// The CPU part of the curtain field's rebuild: each curtain's dense polyline (one texture row each)
// and its footprint map (src/components/aurora/physics/footprint_map.h): the map's frame (projection,
// margin, band) always, its texels when the CPU builds them (else the GPU does, footprint_map_gpu.h).
// A pure function of the curtains' control points, with no GL, so that it can run on a worker thread
// ahead of the frame that needs it and give the same bytes as a build on the frame's own thread.
#include "components/aurora/curtain_model.h"
#include "components/aurora/physics/footprint_map.h"

#include <glm/glm.hpp>

#include <vector>

namespace aurorawall::components::aurora {

// Every curtain's control points (latitude, longitude in degrees), in the scene's order.
using ControlPoints = std::vector<std::vector<glm::dvec2>>;

ControlPoints controlPointsOf(const std::vector<CurtainState>& states);

// The polylines as one RGBA32F texture, width × rows texels (both set here): row c holds curtain c's
// points (unit vector, arclength km), padded with its last point.
std::vector<float> polylineTexels(const std::vector<physics::CurtainPolyline>& polylines, int& width, int& rows);

struct CurtainBuild {
    ControlPoints controlPoints;     // the input
    std::vector<size_t> pointCounts; // per curtain: points of its polyline
    size_t pointTotal = 0;
    // RGBA32F, polylineWidth × polylineRows: per point its unit vector and arclength (km); rows
    // padded with their last point.
    int polylineWidth = 1, polylineRows = 1;
    std::vector<float> polylineTexels;
    // Per curtain, the shader's uniforms of its shape: the polyline's arclength (km, as its last texel
    // holds it) and tan(θ/2) of its largest turn θ, with room for float.
    std::vector<float> lengthsKm, cornerSlopes;
    std::vector<physics::CurtainPolyline> polylines; // in double: the reference map's input
    physics::FootprintMap map;                       // without texels where the GPU builds them
};

// The polylines and the map of the curtains' states (only their control points are read); the map's
// texels only with builder Cpu.
CurtainBuild buildCurtains(const CurtainModel& model, const std::vector<CurtainState>& states, MapBuilder builder);

} // namespace aurorawall::components::aurora
