#pragma once
// Airmass (column density relative to the ground) along a ray segment through an exponential
// atmosphere on a sphere:  I = ∫_{t0}^{t1} exp(−(|o + t·d̂| − R)/H) dt  in km, d̂ = d/|d|.
// The closed forms live once in shaders/physics/atmosphere/*.glsl and are compiled here in float (what the
// GPU runs) and double. Definitions for every method (docs/airmass.md):
//   - signed: I(t1, t0) = −I(t0, t1); a zero-length segment or a zero direction gives 0;
//   - the direction is normalised, t is in km along d̂;
//   - the planet is transparent: a segment below the ground is integrated through it (the renderer
//     clips at the ground itself), with the density capped at e^60 deep inside.
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace aurorawall::physics::atmosphere {

struct AirmassRay {
    glm::dvec3 origin{0.0};     // km, planet centre at the origin
    glm::dvec3 direction{0.0};  // any length; normalised by every method
    double t0 = 0.0;            // km along the unit direction
    double t1 = 0.0;
    double scaleHeight = 8.0;   // H, km
    double planetRadius = 6371.0; // R, km
};

enum class AirmassPrecision { Float32, Float64 };

// One way of computing the airmass. `exact` has no float version (it is the double reference).
struct AirmassMethod {
    std::string name;
    std::string description;
    float (*float32)(glm::vec3 origin, glm::vec3 direction, float t0, float t1, float H, float R);
    double (*float64)(glm::dvec3 origin, glm::dvec3 direction, double t0, double t1, double H, double R);
    std::string glslFunction; // the shader function (same signature, in shaders/physics/atmosphere/airmass_*.glsl); empty for `exact`
};

// The shader modules that define every method's glslFunction, in the order they must be compiled.
inline const char* const kAirmassShaderModules[] = {"physics/constants.glsl", "physics/atmosphere/airmass_common.glsl", "physics/atmosphere/airmass_lawlor.glsl",
                                                    "physics/atmosphere/airmass_tectonics.glsl", "physics/atmosphere/airmass_chapman.glsl",
                                                    "physics/atmosphere/airmass_march.glsl"};

// The method the renderer uses: the asymptotic Chapman expansion with erfcx (shaders/physics/atmosphere/
// airmass_chapman.glsl, airmassChapmanAsymptotic).
inline constexpr const char* kDefaultAirmassMethod = "chapman-asymptotic";

// All methods, the exact reference first.
const std::vector<AirmassMethod>& airmassMethods();

// nullptr when no method has that name.
const AirmassMethod* findAirmassMethod(const std::string& name);

// The ray rounded to float, as the GPU receives it (the accuracy sweep compares on these rays).
AirmassRay roundedToFloat(const AirmassRay& ray);

// Evaluates a method in the given precision; Float32 rounds the ray to float first.
// `exact` is always computed in double.
double evaluateAirmass(const AirmassMethod& method, const AirmassRay& ray, AirmassPrecision precision);

} // namespace aurorawall::physics::atmosphere
