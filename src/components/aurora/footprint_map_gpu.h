#pragma once
// The footprint map built on the GPU (shaders/components/aurora/footprint_build.comp) from the curtains'
// polylines as uploaded for the march: the map of buildFootprintMap (src/components/aurora/physics/
// footprint_map.h), the CPU's build, which stays as the reference it is tested against. The CPU only
// computes the map's frame (footprintMapFrame: a few numbers); the GPU finds every texel's nearest
// curtain point. Nothing is uploaded but uniforms, and the draw that reads the map follows it in the
// GPU's queue without waiting for the CPU. Deterministic: the same inputs give the same bytes on one
// device (order-free atomic minima, no reductions).
//
// In float, the stored distances differ from the exact ones (the CPU's, in double) by at most
// footprintGpuAllowanceKm, which the GPU map's margin adds to the CPU's, so the shader's conservative
// distance stays a lower bound.
#include "components/aurora/aurora.h"
#include "components/aurora/physics/footprint_map.h"
#include "gl/shader_program.h"
#include "gl/texture.h"

#include <string>
#include <vector>

namespace aurorawall::components::aurora {

// Bound in km on |stored − exact| for the GPU's float distances over the map's cap:
//   R·(2·2^-20 + 16u)                the texel centre's direction: cos and sin of θ, each with an absolute
//                                    error below 2^-20 (GLSL leaves it to the implementation; NVIDIA's
//                                    hardware sin/cos stay below 2^-21.4 on [−π, π], CUDA's __sinf/__cosf,
//                                    Mesa's are exact to a few ulps), the rest a few roundings of size 1;
//                                    the seed's rounding to float, u per component
// + d·(2^-20 + 8u)                   the angle 2 atan(|a − b| / |a + b|) of the two directions, relative:
//                                    atan to 2^-20 relative, the lengths and the quotient a few roundings
// with d ≤ R·(2Θ + band radius/R) the largest distance read, u = 2^-24.
double footprintGpuAllowanceKm(const physics::FootprintMap& frame);

class FootprintMapGpu {
public:
    // shaderDir holds components/aurora/.
    explicit FootprintMapGpu(const std::string& shaderDir);
    ~FootprintMapGpu();
    FootprintMapGpu(const FootprintMapGpu&) = delete;
    FootprintMapGpu& operator=(const FootprintMapGpu&) = delete;

    // The frame of the GPU's map: `cpuFrame` (footprintMapFrame of the curtains) with the float allowance
    // added to its margin and to its band's radius.
    static physics::FootprintMap gpuFrame(physics::FootprintMap cpuFrame);

    // Builds the map of `frame` (gpuFrame's) into `map` (RGBA32F, frame.spec.size² texels) from the
    // polylines texture (row c: curtain c's points, pointCounts[c] of them: unit vector, arclength km).
    // Followed by the barriers that let texture fetches and read-backs see the map, and the next build
    // reuse the buffers.
    void build(const physics::FootprintMap& frame, const gl::Texture& polylines, const std::vector<size_t>& pointCounts,
               const gl::Texture& map);

private:
    void ensureBuffers(int size, int coarseSize);
    // One pass over `invocations` items, then the barriers that order what reads its writes next.
    void dispatch(int pass, size_t invocations, GLbitfield barriers = GL_SHADER_STORAGE_BARRIER_BIT);

    gl::Program program_;
    int size_ = 0, coarseSize_ = 0;
    // fine directions, coarse directions, band, coarse distances, flood A, flood B
    unsigned buffers_[6] = {0, 0, 0, 0, 0, 0};
};

} // namespace aurorawall::components::aurora
