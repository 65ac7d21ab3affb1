#pragma once
// The fluid_detail component on the GPU: the Kelvin-Helmholtz flux frames of src/components/fluid_detail/simulation as
// a texture (roles/flux_column_texture.h), with the constants that turn a lookup into a profile of peak 1. Simulated at start-up, or read from the
// on-disk cache (cached_flux_frames.h); the simulation is deterministic and a cache file is read
// only when its checksum and key match, so every rank holds the same frames.
#include "components/fluid_detail/simulation/curtain_detail.h"
#include "gl/shader_program.h"
#include "components/roles/flux_column_texture.h"
#include "components/fluid_detail/fluid_detail.h"
#include "components/roles/curtain_detail.h"

#include <string>
#include <vector>

namespace aurorawall::components::fluid_detail {

using roles::DetailShape;
// The shape of these frames for the aurora's curtain model.
DetailShape detailShape(const simulation::CurtainDetailSpec& spec, const roles::FluxFrames& frames);

class CurtainDetail : public roles::CurtainDetailRenderer {
public:
    explicit CurtainDetail(const Settings& detail);

    std::string precomputationLog() const override { return summary_; }
    void setFrame(gl::Program&, const cluster::FrameState&) override {}
    // Texture unit 3 and the uniforms the curtains' profile reads (roles/flux_column_texture.h).
    void bind(gl::Program& program) const override;

    const DetailShape& shape() const override { return shape_; }

private:
    simulation::CurtainDetailSpec spec_;
    roles::FluxColumnTexture columns_;
    DetailShape shape_;
    std::string summary_;
};

// The simulation parameters for a scene's fluid_detail table (docs/fluid.md).
simulation::CurtainDetailSpec curtainDetailSpec(const Settings& detail);


} // namespace aurorawall::components::fluid_detail
