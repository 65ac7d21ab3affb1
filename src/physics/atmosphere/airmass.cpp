#include "physics/atmosphere/airmass.h"

#include "physics/atmosphere/airmass_exact.h"
#include "common/glsl.h"

// The shared GLSL modules, compiled once in float (bit-faithful to the shader, modulo the driver's
// transcendentals) and once in double.
namespace aurorawall::physics::atmosphere::f32 {
AURORAWALL_GLSL_PRECISION(float)
#include "physics/constants.glsl"
#include "physics/atmosphere/airmass_common.glsl"
#include "physics/atmosphere/airmass_lawlor.glsl"
#include "physics/atmosphere/airmass_tectonics.glsl"
#include "physics/atmosphere/airmass_chapman.glsl"
#include "physics/atmosphere/airmass_march.glsl"
} // namespace aurorawall::physics::atmosphere::f32

namespace aurorawall::physics::atmosphere::f64 {
AURORAWALL_GLSL_PRECISION(double)
#include "physics/constants.glsl"
#include "physics/atmosphere/airmass_common.glsl"
#include "physics/atmosphere/airmass_lawlor.glsl"
#include "physics/atmosphere/airmass_tectonics.glsl"
#include "physics/atmosphere/airmass_chapman.glsl"
#include "physics/atmosphere/airmass_march.glsl"
} // namespace aurorawall::physics::atmosphere::f64

namespace aurorawall::physics::atmosphere {

const std::vector<AirmassMethod>& airmassMethods()
{
    static const std::vector<AirmassMethod> methods{
        {"exact", "double-precision adaptive Gauss-Kronrod quadrature (the reference)", nullptr,
         [](glm::dvec3 o, glm::dvec3 d, double t0, double t1, double H, double R) {
             return exactAirmass(o, d, t0, t1, H, R);
         },
         ""},
        {"lawlor-winitzki", "Lawlor's parabola + Winitzki erf and 0.5*guts erfc, as published (baseline)",
         f32::airmassLawlorWinitzki, f64::airmassLawlorWinitzki, "airmassLawlorWinitzki"},
        {"lawlor-erfcx", "Lawlor's parabola with an accurate scaled erfc and a safe form for short segments",
         f32::airmassLawlorErfcx, f64::airmassLawlorErfcx, "airmassLawlorErfcx"},
        {"tectonics-quadratic", "Tectonics.js quadratic-height approximation, as published",
         f32::airmassTectonics, f64::airmassTectonics, "airmassTectonics"},
        {"chapman-schueler", "differences of Schueler's Chapman approximation (GPU Pro 3)",
         f32::airmassChapmanSchueler, f64::airmassChapmanSchueler, "airmassChapmanSchueler"},
        {"chapman-hdrp", "differences of the Unity HDRP rational Chapman fit",
         f32::airmassChapmanHdrp, f64::airmassChapmanHdrp, "airmassChapmanHdrp"},
        {"chapman-asymptotic", "differences of the first-order asymptotic Chapman function with erfcx (default)",
         f32::airmassChapmanAsymptotic, f64::airmassChapmanAsymptotic, "airmassChapmanAsymptotic"},
        {"march16", "16-step midpoint march (cost yardstick)", f32::airmassMarch16, f64::airmassMarch16, "airmassMarch16"},
    };
    return methods;
}

const AirmassMethod* findAirmassMethod(const std::string& name)
{
    for (const AirmassMethod& method : airmassMethods()) {
        if (method.name == name) return &method;
    }
    return nullptr;
}

AirmassRay roundedToFloat(const AirmassRay& ray)
{
    return {glm::dvec3(glm::vec3(ray.origin)),
            glm::dvec3(glm::vec3(ray.direction)),
            double(float(ray.t0)),
            double(float(ray.t1)),
            double(float(ray.scaleHeight)),
            double(float(ray.planetRadius))};
}

double evaluateAirmass(const AirmassMethod& method, const AirmassRay& ray, AirmassPrecision precision)
{
    if (precision == AirmassPrecision::Float32 && method.float32) {
        return method.float32(glm::vec3(ray.origin), glm::vec3(ray.direction), float(ray.t0), float(ray.t1),
                              float(ray.scaleHeight), float(ray.planetRadius));
    }
    return method.float64(ray.origin, ray.direction, ray.t0, ray.t1, ray.scaleHeight, ray.planetRadius);
}

} // namespace aurorawall::physics::atmosphere
