#pragma once
// The march's work per pixel, counted on the GPU (shaders/render/work_counts.glsl) when a
// TileRenderer is made with CountWork::Yes: a measure of progress that needs no GPU clock. Each
// pixel counts its march steps (footprint map reads), the curtains evaluated near a step, the
// sub-steps integrated and the march's texture fetches. A GPU runs 32 neighbouring invocations in
// lockstep (the compute march's 8x4-pixel workgroups), so each waits for the slowest: the mean over
// 8x4 blocks of each block's largest count is what the hardware pays.
#include <glm/glm.hpp>

#include <array>
#include <vector>

namespace aurorawall::render {

enum class CountWork { No, Yes };

// What a pixel's work, the float target's second attachment (gl/float_target.h), holds:
//   Samples         1 + the ray's march samples (shaders/render/work_counts.glsl, gRayWork): the load
//                   balancer's measure;
//   ShaderClock     the GPU clock cycles the pixel's ray took (GL_ARB_shader_clock, clock2x32ARB
//                   around the ray; on a GPU a warp's lanes finish together, so neighbours share the
//                   slowest's time, which is what they cost);
//   TextureFetches  1 + the march's texture fetches (the counters above): the dependent reads that
//                   dominate a GPU's time per pixel, where there is no clock.
enum class PixelWork { Samples, ShaderClock, TextureFetches };

constexpr int kWorkQuantities = 4;
inline constexpr const char* kWorkQuantityNames[kWorkQuantities] = {"march_steps", "curtain_evaluations",
                                                                   "sub_steps", "texture_fetches"};
constexpr int kWarpWidth = 8, kWarpHeight = 4; // the compute march's workgroup (main.comp): 32 pixels

struct WorkSummary {
    std::array<double, kWorkQuantities> meanPerPixel{};
    std::array<double, kWorkQuantities> meanBlockMax{}; // over the 8x4 blocks (partial ones at the edges count)
};

// counts: kWorkQuantities floats per pixel, rows bottom-up (GL's), size.x * size.y pixels; the blocks
// are those of the compute march's workgroups, from the bottom-left corner.
WorkSummary summarizeWork(const std::vector<float>& counts, glm::ivec2 size);

} // namespace aurorawall::render
