#pragma once
// Everything the shader needs for one frame, computed on the CPU in double precision and
// rounded to float only at the end: positions relative to the camera, altitudes, and phases
// of periodic motions reduced modulo their period (so animation time 1e9 s loses nothing).
#include "cluster/frame_state.h"
#include "gl/shader_program.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace aurorawall::render {

struct CurtainUniforms {
    std::vector<glm::vec4> points; // unit vector, arclength from the curtain's first point (km)
    std::vector<glm::vec2> ranges;  // first point, point count (small integers, exact in float)
    std::vector<glm::vec4> shapes;  // energy flux erg cm^-2 s^-1, half-thickness km, energy keV, fold amplitude km
    std::vector<glm::vec2> folds;   // wavenumber rad/km, phase rad in [0, 2 pi)
};

CurtainUniforms curtainUniforms(const scene::Scene& scene, double timeS);

// Sets the per-frame uniforms of every listed component on `program`.
void applySceneUniforms(gl::Program& program, const scene::Scene& scene, const cluster::FrameState& frame);

} // namespace aurorawall::render
