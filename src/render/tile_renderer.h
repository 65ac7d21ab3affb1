#pragma once
// Draws tiles of the wall: for each tile, one pass of the raymarcher into a float target, as a
// compute dispatch of 8x4-pixel workgroups or a fragment shader over a full-screen triangle
// (march_shader.h; the same image either way). The program is compiled, and the tables of the scene's components precomputed, once
// per rank; everything that changes per frame comes from the master's FrameState only.
#include "cluster/frame_state.h"
#include "gl/float_target.h"
#include "gl/full_screen_triangle.h"
#include "gl/shader_program.h"
#include "render/march_shader.h"
#include "render/work_counts.h"
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
    // With CountWork::Yes (compute stage only, else std::invalid_argument) every tile also counts
    // its work per pixel (work_counts.h), read with workCounts. pixelWork: what the target's work
    // attachment holds (work_counts.h; ShaderClock needs GL_ARB_shader_clock, else std::invalid_argument).
    TileRenderer(const scene::Scene& scene, const std::string& shaderDir, MarchStage stage,
                 CountWork countWork = CountWork::No, PixelWork pixelWork = PixelWork::Samples);
    // The same in the stage preferred for the current context's renderer (preferredMarchStage).
    TileRenderer(const scene::Scene& scene, const std::string& shaderDir);

    // Once per frame, before its tiles: the uniforms shared by every tile and the per-frame
    // component data (curtains at this time), uploaded to textures shared by all contexts.
    void setFrame(const cluster::FrameState& frame);

    // Renders the tile whose pixel rays are `rays` into `target` (its size is the tile's size),
    // drawing with `triangle` (vertex arrays belong to one context). The ray vectors are rotated
    // from the wall frame into the planet frame in double precision, the flat wall's with the frame's
    // zoom (cluster::wallToPlanet), the dome master's without.
    void renderTile(const wall::TileRays& rays, gl::FloatTarget& target, const gl::FullScreenTriangle& triangle);
    // Once a frame, after its first tile is submitted (and flushed) and before the CPU waits for it: the
    // components' work for the next frame that the draw hides (scene::ComponentRenderer::whileDrawing).
    void whileDrawing();

    MarchStage stage() const { return stage_; }
    PixelWork pixelWork() const { return pixelWork_; }

    // The last tile's work counts (CountWork::Yes): kWorkQuantities floats per pixel, rows bottom-up.
    // Throws std::logic_error without counting or for another size than the last tile's.
    std::vector<float> workCounts(glm::ivec2 size) const;

    // One line per table precomputed at start-up for the scene's components; empty when none is needed.
    const std::vector<std::string>& precomputationLog() const { return precomputationLog_; }
    // The components' GPU parts, in registry order.
    const std::vector<std::unique_ptr<scene::ComponentRenderer>>& components() const { return components_; }
    // The last setFrame's wall time (ms) of each component's setFrame, in components() order.
    const std::vector<double>& componentFrameMs() const { return componentFrameMs_; }
    // What the last setFrame computed per frame (e.g. the curtains' footprint map); may be empty.
    std::string frameLog() const;

private:
    const scene::Scene& scene_;
    MarchStage stage_;
    CountWork countWork_;
    PixelWork pixelWork_;
    gl::Program program_;
    std::unique_ptr<gl::Texture> workCounts_; // RGBA32F, the last tile's size
    glm::dmat3 wallToPlanet_{1.0}; // with the frame's zoom (cluster::wallToPlanet)
    glm::dmat3 domeToPlanet_{1.0}; // the camera's axes alone
    double zoom_ = 1.0;
    glm::dvec3 viewForward_{0.0, 0.0, -1.0}; // the camera's view direction, planet frame
    std::vector<std::unique_ptr<scene::ComponentRenderer>> components_;
    std::vector<double> componentFrameMs_;
    std::vector<std::string> precomputationLog_;
};

} // namespace aurorawall::render
