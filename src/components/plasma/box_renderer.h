#pragma once
// The plasma component's GPU part: the curtain detail (PlasmaDetail, which the aurora samples) and
// the box's density frames for shaders/components/plasma/plasma_box*.glsl. With kind = "box" the
// frames are n/n₀ on the box's cells, stacked along z frame after frame in one 3D texture (linear,
// periodic across the field); with device = "gpu" one frame, the box's simulation run live on the
// GPU (live_pic.h) and stepped in setFrame to the clock's step (boxStep); with kind = "curls" a
// single zero texel and no steps, so the box's step adds nothing.
#include "components/plasma/plasma.h"
#include "components/plasma/plasma_detail.h"

#include <glm/glm.hpp>

namespace aurorawall::components::plasma {

class BoxRenderer : public PlasmaDetail {
public:
    // scene: for the curtain detail (PlasmaDetail).
    BoxRenderer(const Settings& plasma, const scene::Scene& scene, double planetRadiusKm);

    std::string precomputationLog() const override { return boxSummary_; }
    // The box's centre from where the rays start (double, then float), its frame position at this time
    // (device = "gpu": the live run stepped to this time's step, its frame uploaded, waited for).
    void setFrame(gl::Program& program, const cluster::FrameState& frame) override;
    // Texture unit 9: uPlasmaBoxFrames; and the curtain detail's.
    void bind(gl::Program& program) const override;

private:
    bool box_;
    Settings settings_;
    glm::dvec3 centreKm_{0.0};  // planet frame
    double reachRadiusKm_;      // the scene's (scene::Scene::reachRadiusKm), for where rays start
    glm::dmat3 axes_{1.0};      // columns: east, north, up at the centre (z along the field)
    glm::vec3 rgbPerDensityKm_{0.0f};
    std::unique_ptr<LivePic> liveBox_;
    gl::Texture boxFrames_;
    std::string boxSummary_;
};

} // namespace aurorawall::components::plasma
