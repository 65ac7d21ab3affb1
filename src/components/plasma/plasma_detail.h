#pragma once
// The plasma component on the GPU: the electron strip's density as curtain flux frames
// (roles/flux_column_texture.h) with the uniforms of the curtains' profile, as the other provider of
// the curtain detail binds them.
//   device = "cpu": the frames simulated at start-up (sheet_frames.h), the curtain's detail phase
//     choosing and blending frames in the shader.
//   device = "gpu": one frame, the strip's simulation run live on the GPU (live_pic.h) and stepped in
//     setFrame to the step of the first curtain's detail phase at the frame's time (curlsStep); the
//     shader's frame lookup pinned to that one frame (frame count 1).
#include "components/plasma/live_pic.h"
#include "components/plasma/plasma.h"
#include "components/roles/curtain_detail.h"
#include "components/roles/flux_column_texture.h"

#include <memory>
#include <string>

namespace aurorawall::components::plasma {

class PlasmaDetail : public roles::CurtainDetailRenderer {
public:
    // scene: its curtains' provider gives the first curtain's detail phase, which drives the live run.
    PlasmaDetail(const Settings& plasma, const scene::Scene& scene);

    std::string precomputationLog() const override { return summary_; }
    // device = "gpu": steps the live run to this frame's step and uploads its frame, waited for.
    void setFrame(gl::Program&, const cluster::FrameState& frame) override;
    // Texture unit 3: uFluxTables, with uFluxStrip and uFluxLayout.
    void bind(gl::Program& program) const override;

    const roles::DetailShape& shape() const override { return shape_; }

private:
    SheetFramesSpec spec_;
    roles::DetailPhase phase_; // the first curtain's (none: 0)
    std::unique_ptr<LivePic> live_;
    roles::FluxColumnTexture columns_;
    roles::FluxFrames liveFrame_; // device = "gpu": the live run's frame, its flux replaced each step
    roles::DetailShape shape_;
    std::string summary_;
};

} // namespace aurorawall::components::plasma
