#pragma once
// The per-frame uniforms of the camera and the layers, computed on the CPU in double precision
// and rounded to float only at the end (positions relative to the camera, altitudes). The
// curtains' per-frame data is render/curtain_field.h.
#include "cluster/frame_state.h"
#include "gl/shader_program.h"
#include "scene/scene.h"

#include <glm/glm.hpp>


namespace aurorawall::render {

// Sets the per-frame uniforms of every listed component on `program`.
void applySceneUniforms(gl::Program& program, const scene::Scene& scene, const cluster::FrameState& frame);

} // namespace aurorawall::render
