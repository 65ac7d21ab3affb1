#include "physics/atmosphere/sky.h"

#include "common/glsl.h"

#include <stdexcept>

// The shared modules the sky needs, compiled in float and double. This file's own copies (unnamed
// namespaces): airmass.cpp compiles the airmass modules into the same f32 and f64.
namespace aurorawall::physics::atmosphere::f32 {
namespace {
AURORAWALL_GLSL_PRECISION(float)
#include "physics/constants.glsl"
#include "physics/atmosphere/airmass_common.glsl"
#include "physics/atmosphere/airmass_chapman.glsl"
#include "physics/atmosphere/sky.glsl"
} // namespace
} // namespace aurorawall::physics::atmosphere::f32

namespace aurorawall::physics::atmosphere::f64 {
namespace {
AURORAWALL_GLSL_PRECISION(double)
#include "physics/constants.glsl"
#include "physics/atmosphere/airmass_common.glsl"
#include "physics/atmosphere/airmass_chapman.glsl"
#include "physics/atmosphere/sky.glsl"
} // namespace
} // namespace aurorawall::physics::atmosphere::f64

namespace aurorawall::physics::atmosphere {
namespace {

// The lights as the module's two arrays (SKY_MAX_LIGHTS entries, the first lights.size() used).
template <typename Real>
struct SkyLightArrays {
    using Vec3 = glm::vec<3, Real, glm::defaultp>;
    Vec3 directions[kSkyMaxLights];
    Vec3 illuminances[kSkyMaxLights];

    explicit SkyLightArrays(const std::vector<SkyLight>& lights)
    {
        for (size_t l = 0; l < lights.size(); ++l) {
            directions[l] = Vec3(lights[l].direction);
            illuminances[l] = Vec3(lights[l].illuminanceLux);
        }
    }
};

} // namespace

glm::dvec3 skyRadiance(const SkyView& view, const SkyAtmosphereParameters& atmosphere,
                       const std::vector<SkyLight>& lights, SkyLightMethod method, int viewSteps, int lightSteps,
                       AirmassPrecision precision)
{
    if (lights.size() > size_t(kSkyMaxLights)) throw std::invalid_argument("skyRadiance: more than 8 lights");
    const int lightCount = int(lights.size());
    const int lightMethod = method == SkyLightMethod::ClosedForm ? f64::SKY_LIGHT_CLOSED_FORM
                                                                 : f64::SKY_LIGHT_NESTED_MARCH;
    if (precision == AirmassPrecision::Float32) {
        SkyLightArrays<float> arrays(lights);
        f32::SkyAtmosphere air{float(atmosphere.planetRadiusKm), float(atmosphere.topRadiusKm),
                                   float(atmosphere.scaleHeightKm), glm::vec3(atmosphere.rayleighScatteringPerKm)};
        return glm::dvec3(f32::skyScattering(glm::vec3(view.origin), glm::vec3(view.direction), float(view.tMax),
                                                 air, lightCount, arrays.directions, arrays.illuminances, viewSteps,
                                                 lightMethod, lightSteps));
    }
    SkyLightArrays<double> arrays(lights);
    f64::SkyAtmosphere air{atmosphere.planetRadiusKm, atmosphere.topRadiusKm, atmosphere.scaleHeightKm,
                               atmosphere.rayleighScatteringPerKm};
    return f64::skyScattering(view.origin, view.direction, view.tMax, air, lightCount, arrays.directions,
                                  arrays.illuminances, viewSteps, lightMethod, lightSteps);
}

} // namespace aurorawall::physics::atmosphere
