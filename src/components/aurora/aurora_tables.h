#pragma once
// The aurora component's precomputed tables on the GPU: Lazarev deposition over altitude and
// electron energy (in decibels) and the emission-line yields over altitude (src/components/aurora/physics), sampled
// by shaders/components/aurora/deposition.glsl. Built once per rank at start-up, deterministically, so every
// rank holds the same bytes.
#include "gl/shader_program.h"
#include "gl/texture.h"
#include "components/aurora/aurora.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace aurorawall::components::aurora {

class AuroraTables {
public:
    explicit AuroraTables(const Settings& aurora);

    // Binds the tables to texture units 0 and 1 and sets their uniforms (per context: texture
    // bindings are not shared between the GLFW windows' contexts).
    void bind(gl::Program& program) const;

    // "aurora deposition table 1081 x 128 (maxwellian), line yields 1081: 12.3 ms"
    const std::string& summary() const { return summary_; }

private:
    gl::Texture deposition_;
    gl::Texture lineYield_;
    glm::vec4 axes_{0.0f};
    glm::vec2 size_{0.0f};
    std::vector<glm::vec3> lineRgb_; // linear sRGB of one rayleigh of each line
    std::string summary_;
};

} // namespace aurorawall::components::aurora
