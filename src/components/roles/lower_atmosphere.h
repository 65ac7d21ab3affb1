#pragma once
// The role "lower atmosphere": the dense air whose extinction and scattering the ray's later steps see
// through (scene/shell.h, Shell::LowerAtmosphere). The layers composited behind it as a whole must lie
// above its top, and a component that follows its own light through it (a cloud deck's sunlight)
// needs its air: both ask the scene's provider through this interface.
#include "scene/component.h"

#include <glm/glm.hpp>

#include <optional>
#include <string>

namespace aurorawall::components::roles {

// The role's name in Component::provides and needs, Scene::provider and the define HAS_LOWER_ATMOSPHERE.
inline constexpr const char* kLowerAtmosphere = "lower atmosphere";

// The air: an exponential density from the ground up to its top.
struct LowerAir {
    double topKm = 0.0;               // the top's altitude above the ground (km)
    double scaleHeightKm = 0.0;       // the density's scale height (km)
    glm::dvec3 extinctionPerKm{0.0};  // extinction at the ground per km, for the R, G, B primaries
    std::string topKey;               // the scene key that sets the top, for errors ("TABLE.top_km")
};

// The provider component's part (a provider derives from it besides scene::Component).
class LowerAtmosphereProvider {
public:
    virtual ~LowerAtmosphereProvider() = default;
    // Its air as the scene holds it; while a scene is read, from the provider's table on (the
    // registry lists the provider before the components that ask).
    virtual LowerAir air(const scene::Scene& scene) const = 0;
};

// The air of the scene's provider of the lower atmosphere; none when it lists none.
std::optional<LowerAir> lowerAir(const scene::Scene& scene);

} // namespace aurorawall::components::roles
