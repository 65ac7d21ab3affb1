#pragma once
// The role "curtain detail": small-scale structure of the aurora's curtains, given as flux frames on
// a strip along the curtain (FluxFrames, roles/flux_frames.h) that the aurora's curtain profile samples
// (shaders/components/aurora/curtain_profile.glsl). Provided by fluid_detail and by plasma; the aurora
// uses it through this interface only, finding the provider by the role's name.
#include "components/roles/flux_frames.h"
#include "scene/component.h"

#include <functional>
#include <memory>
#include <vector>

namespace aurorawall::components::roles {

// The role's name in Component::provides, FindRenderer and Scene::provider.
inline constexpr const char* kCurtainDetail = "curtain detail";
// The role "curtains": the curtains whose profile samples the detail. A provider of the curtain
// detail needs it (Component::needs).
inline constexpr const char* kCurtains = "curtains";

// How the frames shape a curtain across and along it: what the aurora's curtain model needs.
struct DetailShape {
    double fluxWidthKm = 0.0;          // standard deviation of the flux across the strip at frame 0 (km)
    double reachKm = 0.0;              // the largest reach of any frame (strip km)
    std::vector<double> frameReachKm;  // each frame's (frameReachesKm); empty: reachKm for every frame
    double stripLengthKm = 0.0;        // the pattern's period along the curtain
    // Frame 0 is a Gaussian of unit integral across: its peak is 1/(sigma sqrt(2 pi)); scaling by
    // sigma sqrt(2 pi) makes the smooth curtain's peak 1.
    double peakScale = 1.0;

    // The reach (strip km) of the frames blended at detail phase `phase` (0 ... 1, frame
    // phase * (frames - 1)): the larger of the two, and of a neighbour where the phase lies within
    // rounding of a frame (the shader computes the blend in float).
    double reachAtPhaseKm(double phase) const;
    // Sets frameReachKm to these (one per frame, at least one) and reachKm to the largest.
    void setFrameReaches(std::vector<double> reachesKm);
};

// The provider's GPU part: it binds the frames for the curtain profile and tells their shape.
class CurtainDetailRenderer : public scene::ComponentRenderer {
public:
    virtual const DetailShape& shape() const = 0;
};

// The provider component's part for the CPU reference (a provider derives from it besides
// scene::Component).
class CurtainDetailProvider {
public:
    virtual ~CurtainDetailProvider() = default;
    // The frames its renderer uploads, from the table cache.
    virtual std::shared_ptr<const roles::FluxFrames> referenceFrames(const scene::Scene& scene) const = 0;
    // The shape of `frames` (its own, or others on the same strip) and the strip's width (km).
    virtual DetailShape referenceShape(const scene::Scene& scene, const roles::FluxFrames& frames) const = 0;
    virtual double stripWidthKm(const scene::Scene& scene) const = 0;
};

// The scene's provider of curtain detail, null when it lists none.
const CurtainDetailProvider* curtainDetailProvider(const scene::Scene& scene);
// Its frames (CurtainDetailProvider::referenceFrames), null when the scene lists no provider.
std::shared_ptr<const roles::FluxFrames> curtainDetailFrames(const scene::Scene& scene);

// The detail phase (0 smooth ... 1 turbulent) of a curtain over animation time (s).
using DetailPhase = std::function<double(double timeS)>;

// The provider of the curtains, as a provider of their detail sees them (a provider derives from it
// besides scene::Component).
class CurtainsProvider {
public:
    virtual ~CurtainsProvider() = default;
    // The detail phase of the scene's first curtain, its detail on a strip `stripLengthKm` long (km):
    // 0 at every time when the scene has no curtain. It holds a copy of what it needs of the scene.
    virtual DetailPhase firstCurtainDetailPhase(const scene::Scene& scene, double stripLengthKm) const = 0;
};

// The first curtain's detail phase of the scene's provider of the curtains (the provider of the
// detail needs it, so the scene lists one).
DetailPhase firstCurtainDetailPhase(const scene::Scene& scene, double stripLengthKm);

// The reference's role data (ReferenceContext::roleData) holds the frames the aurora's reference
// samples under kCurtainDetail, as a `const roles::FluxFrames*`: the provider's own or others on the
// same strip. These make and read that entry (none for null frames; null when there is none).
scene::RoleData curtainDetailData(const roles::FluxFrames* frames);
const roles::FluxFrames* referenceFrames(const scene::ReferenceContext& context);

} // namespace aurorawall::components::roles
