#include "components/roles/curtain_detail.h"

#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace aurorawall::components::roles {

double DetailShape::reachAtPhaseKm(double phase) const
{
    if (frameReachKm.empty())
        return reachKm;
    const int last = static_cast<int>(frameReachKm.size()) - 1;
    const double p = std::clamp(phase, 0.0, 1.0) * last;
    const int first = std::clamp(static_cast<int>(std::floor(p - 1e-3)), 0, last);
    const int end = std::clamp(static_cast<int>(std::ceil(p + 1e-3)), 0, last);
    return *std::max_element(frameReachKm.begin() + first, frameReachKm.begin() + end + 1);
}

void DetailShape::setFrameReaches(std::vector<double> reachesKm)
{
    frameReachKm = std::move(reachesKm);
    reachKm = *std::max_element(frameReachKm.begin(), frameReachKm.end());
}

const CurtainDetailProvider* curtainDetailProvider(const scene::Scene& scene)
{
    return dynamic_cast<const CurtainDetailProvider*>(scene.provider(kCurtainDetail));
}

DetailPhase firstCurtainDetailPhase(const scene::Scene& scene, double stripLengthKm)
{
    return dynamic_cast<const CurtainsProvider&>(*scene.provider(kCurtains)).firstCurtainDetailPhase(scene, stripLengthKm);
}

std::shared_ptr<const roles::FluxFrames> curtainDetailFrames(const scene::Scene& scene)
{
    const CurtainDetailProvider* provider = curtainDetailProvider(scene);
    return provider ? provider->referenceFrames(scene) : nullptr;
}

scene::RoleData curtainDetailData(const roles::FluxFrames* frames)
{
    if (!frames)
        return {};
    return {{kCurtainDetail, frames}};
}

const roles::FluxFrames* referenceFrames(const scene::ReferenceContext& context)
{
    const auto entry = context.roleData.find(kCurtainDetail);
    return entry == context.roleData.end() ? nullptr : std::any_cast<const roles::FluxFrames*>(entry->second);
}

} // namespace aurorawall::components::roles
