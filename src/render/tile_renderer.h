#pragma once
// Draws tiles of the wall: for each tile, one full-screen pass of the raymarcher into a float
// target. The program is compiled once per rank for the scene's components; the per-frame
// state comes from the master's FrameState only.
#include "cluster/frame_state.h"
#include "gl/float_target.h"
#include "gl/full_screen_triangle.h"
#include "gl/shader_program.h"
#include "render/aurora_tables.h"
#include "scene/scene.h"
#include "wall/tile_rays.h"

#include <memory>
#include <string>
#include <vector>

namespace aurorawall::render {

class TileRenderer {
public:
    // Compiles the raymarcher and precomputes the tables of the scene's components (needs a
    // current context). Throws InputError for unreadable shader files and gl::ShaderError for
    // compile errors.
    TileRenderer(const scene::Scene& scene, const std::string& shaderDir);

    // Sets the uniforms that are the same for every tile of this frame.
    void beginFrame(const cluster::FrameState& frame);

    // Renders the tile whose pixel rays are `rays` into `target` (its size is the tile's size),
    // drawing with `triangle` (vertex arrays belong to one context). The ray vectors are rotated
    // from the wall frame into the planet frame in double precision.
    void renderTile(const wall::TileRays& rays, gl::FloatTarget& target, const gl::FullScreenTriangle& triangle);

    gl::Program& program() { return program_; }

    // One line per table precomputed for the scene's components; empty when none is needed.
    const std::vector<std::string>& precomputationLog() const { return precomputationLog_; }

private:
    const scene::Scene& scene_;
    gl::Program program_;
    std::unique_ptr<AuroraTables> auroraTables_; // only when the scene lists the aurora
    std::vector<std::string> precomputationLog_;
    glm::dmat3 wallToPlanet_{1.0};
};

} // namespace aurorawall::render
