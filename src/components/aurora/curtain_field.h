#pragma once
// The aurora's curtains for one frame, on the GPU: each curtain's spline sampled into a dense
// polyline (one texture row each) on the CPU, and the footprint map that finds the nearest curtain
// point from anywhere (src/components/aurora/physics/footprint_map.h), built from the uploaded
// polylines on the GPU (footprint_map_gpu.h) or on the CPU and uploaded (MapBuilder). Rebuilt every
// frame from the master's animation time, deterministically, so every rank of a wall of like GPUs
// holds the same bytes; kept (with their textures) while the curtains' control points stay exactly
// the same.
//
// While a frame draws, the curtains of the next frame's time as the master announced it
// (cluster::FrameState::nextTimeS) are built on a worker thread; the next update uploads that build
// when its control points are exactly the frame's (a command such as pause or a new time can make
// the next frame differ), and otherwise builds them itself.
#include "gl/shader_program.h"
#include "gl/texture.h"
#include "components/aurora/curtain_build_ahead.h"
#include "components/aurora/curtain_model.h"
#include "components/aurora/footprint_map_gpu.h"

#include <glm/glm.hpp>

#include <memory>
#include <string>
#include <vector>

namespace aurorawall::components::aurora {

// Curtain i's uniforms of shaders/components/aurora/aurora_curtains.glsl in state s, its polyline of
// pointCount points: uCurtainState (peak flux, energy keV, point count, reach km) and uCurtainDetail
// (detail offset km, phase, lateral scale, 0).
glm::vec4 curtainStateUniform(const CurtainModel& model, size_t i, const CurtainState& s, size_t pointCount);
glm::vec4 curtainDetailUniform(const CurtainModel& model, size_t i, const CurtainState& s);

class CurtainField {
public:
    // builder: Cpu or Gpu (not Auto); shaderDir holds components/aurora/ (the GPU's map build).
    CurtainField(const CurtainModel& model, MapBuilder builder, const std::string& shaderDir);

    // Evaluates the keyframes at timeS; rebuilds (or takes the build made ahead) and uploads the
    // polylines and the map when the control points differ from the last build's. Then starts
    // building the curtains of nextTimeS ahead, when they differ from this frame's (NaN: not known).
    void update(double timeS, double nextTimeS);

    // Texture units 4 and 5 and the curtain uniforms of shaders/components/aurora/aurora_curtains.glsl.
    void bind(gl::Program& program) const;

    // Each curtain's electron energy (keV) at the last update's time.
    std::vector<float> energiesKeV() const;

    // The uploaded polylines and footprint map (valid after the first update).
    const gl::Texture& polylines() const { return *polylines_; }
    const gl::Texture& footprintMap() const { return *footprint_; }

    // Updates whose control points changed, and how many of those took the build made ahead.
    size_t rebuilds() const { return rebuilds_; }
    size_t rebuildsBuiltAhead() const { return rebuildsBuiltAhead_; }

    // "curtains: 5, 2311 points, footprint map 512^2 on the GPU (radius 21.3 deg, margin 2.9 km), rebuilt:
    //  0.4 ms, built ahead: 7 of 9 rebuilds"
    const std::string& summary() const { return summary_; }

private:
    void upload(const CurtainBuild& build);
    void buildAhead(double nextTimeS);

    const CurtainModel& model_;
    CurtainBuildAhead ahead_;
    std::unique_ptr<FootprintMapGpu> gpuMap_; // null: the CPU builds the map
    size_t rebuilds_ = 0, rebuildsBuiltAhead_ = 0;
    ControlPoints controlPoints_; // of the last build
    std::vector<size_t> pointCounts_;
    size_t pointTotal_ = 0;
    double angularRadiusDeg_ = 0.0;
    std::unique_ptr<gl::Texture> polylines_;
    std::unique_ptr<gl::Texture> footprint_;
    std::vector<glm::vec4> state_;  // per curtain: peak flux, energy keV, point count, reach km
    std::vector<float> lengthsKm_;  // per curtain: its polyline's arclength (km), as the last point's texel holds it
    std::vector<float> cornerSlopes_; // per curtain: tan(θ/2) of its polyline's largest turn θ, with room for float
    std::vector<glm::vec4> detailUniform_; // per curtain: offset km, phase, lateral scale, 0
    float reachKm_ = 0.0f;        // the largest of state_'s reaches among the curtains with flux
    glm::vec3 centre_{0.0f}, east_{0.0f};
    float angularRadius_ = 0.0f, size_ = 0.0f, marginKm_ = 0.0f;
    std::string summary_;
};

} // namespace aurorawall::components::aurora
