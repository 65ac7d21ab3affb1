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
// (cluster::FrameState::nextTimeS) are built on a worker thread; the next update uses that build
// when its control points are exactly the frame's (a command such as pause or a new time can make
// the next frame differ), and otherwise builds them itself. Where the CPU builds the map, uploadAhead
// puts that build into a second set of textures while the frame draws, so the next update only
// swaps the two sets instead of uploading 4 MiB.
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
    // While the frame of the last update draws (the CPU's map only; nothing on the GPU, whose map is
    // built in compute shaders at the update): waits for the build made ahead and uploads it into the
    // textures that frame does not read.
    void uploadAhead();

    // Texture units 4 and 5 and the curtain uniforms of shaders/components/aurora/aurora_curtains.glsl.
    void bind(gl::Program& program) const;

    // Each curtain's electron energy (keV) at the last update's time.
    std::vector<float> energiesKeV() const;

    // The uploaded polylines and footprint map (valid after the first update).
    const gl::Texture& polylines() const { return *front_.polylines; }
    const gl::Texture& footprintMap() const { return *front_.footprint; }

    // Updates whose control points changed, how many of those took the build made ahead, and how many
    // found it uploaded while the frame before drew.
    size_t rebuilds() const { return rebuilds_; }
    size_t rebuildsBuiltAhead() const { return rebuildsBuiltAhead_; }
    size_t rebuildsUploadedAhead() const { return rebuildsUploadedAhead_; }

    // "curtains: 5, 2311 points, footprint map 512^2 on the GPU (radius 21.3 deg, margin 2.9 km), rebuilt:
    //  0.4 ms, built ahead: 7 of 9 rebuilds, uploaded ahead: 6"
    const std::string& summary() const { return summary_; }

private:
    // One build as uploaded: its textures and what the shader needs of it.
    struct Uploaded {
        bool holdsBuild = false;
        ControlPoints controlPoints;
        std::vector<size_t> pointCounts;
        size_t pointTotal = 0;
        std::vector<float> lengthsKm;    // per curtain: its polyline's arclength (km), as the last point's texel holds it
        std::vector<float> cornerSlopes; // per curtain: tan(θ/2) of its polyline's largest turn θ, with room for float
        std::unique_ptr<gl::Texture> polylines;
        std::unique_ptr<gl::Texture> footprint;
        glm::vec3 centre{0.0f}, east{0.0f};
        float angularRadius = 0.0f, size = 0.0f, marginKm = 0.0f;
        double angularRadiusDeg = 0.0;
    };
    void upload(const CurtainBuild& build, Uploaded& into);
    void buildAhead(double nextTimeS);

    const CurtainModel& model_;
    CurtainBuildAhead ahead_;
    std::unique_ptr<FootprintMapGpu> gpuMap_; // null: the CPU builds the map
    size_t rebuilds_ = 0, rebuildsBuiltAhead_ = 0, rebuildsUploadedAhead_ = 0;
    Uploaded front_; // the frame's, which its draw reads
    Uploaded back_;  // the next frame's predicted build, uploaded while the frame draws (uploadAhead)
    std::vector<glm::vec4> state_;  // per curtain: peak flux, energy keV, point count, reach km
    std::vector<glm::vec4> detailUniform_; // per curtain: offset km, phase, lateral scale, 0
    float reachKm_ = 0.0f;        // the largest of state_'s reaches among the curtains with flux
    std::string summary_;
};

} // namespace aurorawall::components::aurora
