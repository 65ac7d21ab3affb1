#pragma once
// The plasma component on the GPU: the electron strip's density frames (sheet_frames.h) as a 3D
// texture (along x, across y, frame z; linear filtering, periodic along) with the uniforms of
// shaders/components/aurora/curtain_profile.glsl, as fluid_detail binds them.
#include "components/fluid_detail/curtain_detail.h"
#include "components/plasma/plasma.h"
#include "gl/texture.h"
#include "scene/component.h"

#include <string>

namespace aurorawall::components::plasma {

class PlasmaDetail : public scene::ComponentRenderer {
public:
    explicit PlasmaDetail(const Settings& plasma);

    std::string precomputationLog() const override { return summary_; }
    void setFrame(gl::Program&, const cluster::FrameState&) override {}
    // Texture unit 3: uFluxFrames and uFluxStrip.
    void bind(gl::Program& program) const override;

    const fluid_detail::DetailShape& shape() const { return shape_; }

private:
    SheetFramesSpec spec_;
    gl::Texture frames_;
    fluid_detail::DetailShape shape_;
    std::string summary_;
};

} // namespace aurorawall::components::plasma
