#include "components/roles/lower_atmosphere.h"

#include "scene/scene.h"

namespace aurorawall::components::roles {

std::optional<LowerAir> lowerAir(const scene::Scene& scene)
{
    if (const auto* provider = dynamic_cast<const LowerAtmosphereProvider*>(scene.provider(kLowerAtmosphere)))
        return provider->air(scene);
    return std::nullopt;
}

} // namespace aurorawall::components::roles
