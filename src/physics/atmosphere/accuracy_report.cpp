#include "physics/atmosphere/accuracy_report.h"

#include "physics/atmosphere/airmass_accuracy.h"
#include "physics/atmosphere/airmass_exact.h"
#include "physics/atmosphere/shader_benchmark.h"
#include "physics/atmosphere/sky_accuracy.h"
#include "gl/context.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ostream>
#include <string>
#include <vector>

namespace aurorawall::physics::atmosphere {
namespace {

// Copies of the item set per dispatch: enough invocations to fill a GPU, few on llvmpipe.
int copiesOf(const AccuracyReportSettings& settings)
{
    if (settings.copies > 0) return settings.copies;
    return gl::isSoftwareRenderer(gl::currentRendererName()) ? 1 : 64;
}

std::string format(const char* pattern, double a)
{
    char text[64];
    std::snprintf(text, sizeof text, pattern, a);
    return text;
}

// The airmass kernel: inputs are three vec4 per ray, (origin, t0), (direction, t1), (H, R, 0, 0).
// AIRMASS_FUNCTION is a method's glslFunction, or airmassBaseline for the empty loop.
const char* kAirmassKernel = R"(float airmassBaseline(vec3 o, vec3 d, float t0, float t1, float H, float R)
{
    return t1 - t0 + H + R + o.x + d.x;
}

vec4 evaluate(int item, float jitter)
{
    vec4 a = inputs[3 * item];
    vec4 b = inputs[3 * item + 1];
    vec4 c = inputs[3 * item + 2];
    return vec4(AIRMASS_FUNCTION(a.xyz, b.xyz, a.w + jitter, b.w, c.x, c.y));
}
)";

// The sky kernel: inputs are two vec4 per view, (origin, tMax), (direction, 0). SKY_FUNCTION is
// skySingleScattering, skySingleScatteringNested or skyBaseline.
const char* kSkyKernel = R"(uniform float uSkyPlanetRadiusKm;
uniform float uSkyTopRadiusKm;
uniform float uSkyScaleHeightKm;
uniform vec3 uSkyRayleighScatteringPerKm;
uniform int uSkyLightCount;
uniform vec3 uSkyLightDirection[SKY_MAX_LIGHTS];
uniform vec3 uSkyLightIlluminanceLux[SKY_MAX_LIGHTS];

vec4 evaluate(int item, float jitter)
{
    vec4 a = inputs[2 * item];
    vec4 b = inputs[2 * item + 1];
    SkyAtmosphere air = SkyAtmosphere(uSkyPlanetRadiusKm, uSkyTopRadiusKm, uSkyScaleHeightKm, uSkyRayleighScatteringPerKm);
#if defined(SKY_BASELINE)
    return vec4(a.xyz + b.xyz + uSkyLightDirection[0] * float(uSkyLightCount), a.w + jitter);
#elif defined(SKY_NESTED)
    return vec4(skySingleScatteringNested(a.xyz, b.xyz, a.w + jitter, air, uSkyLightCount, uSkyLightDirection,
                                          uSkyLightIlluminanceLux, SKY_VIEW_STEPS, SKY_LIGHT_STEPS), 0.0);
#else
    return vec4(skySingleScattering(a.xyz, b.xyz, a.w + jitter, air, uSkyLightCount, uSkyLightDirection,
                                    uSkyLightIlluminanceLux, SKY_VIEW_STEPS), 0.0);
#endif
}
)";

std::vector<glm::vec4> airmassInputs(const std::vector<AirmassRay>& rays)
{
    std::vector<glm::vec4> inputs;
    for (const AirmassRay& ray : rays) {
        inputs.emplace_back(glm::vec3(ray.origin), float(ray.t0));
        inputs.emplace_back(glm::vec3(ray.direction), float(ray.t1));
        inputs.emplace_back(float(ray.scaleHeight), float(ray.planetRadius), 0.0f, 0.0f);
    }
    return inputs;
}

ShaderBenchmarkResult runAirmassKernel(const std::string& function, const std::vector<glm::vec4>& inputs, int rayCount,
                                       const ShaderBenchmarkSettings& settings)
{
    gl::ShaderSource source;
    source.defines.push_back("AIRMASS_FUNCTION " + function);
    for (const char* module : kAirmassShaderModules) source.modules.push_back(readShaderModule(module));
    source.modules.push_back({"airmass_kernel.comp", kAirmassKernel});
    return runShaderBenchmark(source, inputs, rayCount, settings, [](gl::Program&) {});
}

} // namespace

std::vector<double> evaluateAirmassInShader(const std::string& glslFunction, const std::vector<AirmassRay>& rays)
{
    const ShaderBenchmarkResult result =
        runAirmassKernel(glslFunction, airmassInputs(rays), int(rays.size()), ShaderBenchmarkSettings{});
    std::vector<double> values;
    for (const glm::vec4& value : result.firstResults) values.push_back(value.x);
    return values;
}

namespace {

std::string describeRay(const AirmassRay& ray)
{
    double distance = glm::length(ray.origin);
    double cosZenith = distance > 0.0 ? glm::dot(ray.origin / distance, glm::normalize(ray.direction)) : 0.0;
    char text[160];
    std::snprintf(text, sizeof text, "%.6g %.6f %.6g %.6g %g", distance - ray.planetRadius, cosZenith, ray.t0, ray.t1,
                  ray.scaleHeight);
    return text;
}

// Max over rays of |a − b| / max(|exact|, floor), both finite.
double maxRelativeDifference(const std::vector<double>& a, const std::vector<double>& b, const std::vector<double>& exact,
                             double floor)
{
    double worst = 0.0;
    for (size_t i = 0; i < a.size(); ++i)
        if (std::isfinite(a[i]) && std::isfinite(b[i]))
            worst = std::max(worst, std::abs(a[i] - b[i]) / std::max(std::abs(exact[i]), floor));
    return worst;
}

} // namespace

void printAirmassAccuracy(const AccuracyReportSettings& settings, std::ostream& out)
{
    const std::vector<AirmassRay> rays = airmassAccuracyRays();
    const int rayCount = int(rays.size());
    // Mixed: neighbouring invocations take different rays, one evaluation after the other (latency).
    // Throughput: the same with 4 independent chains of evaluations per invocation, which the CPU (or a
    // GPU's scheduler) can overlap, as it overlaps independent pixels. Coherent: a work group per ray,
    // with 1/64 of the repetitions, so that all three do the same number of evaluations.
    ShaderBenchmarkSettings timing;
    timing.repeat = settings.airmassRepeat;
    timing.copies = copiesOf(settings);
    timing.runs = 7;
    ShaderBenchmarkSettings coherent = timing;
    coherent.coherent = true;
    coherent.repeat = std::max(1, timing.repeat / 64);
    ShaderBenchmarkSettings throughput = timing;
    throughput.chains = 4;
    const std::vector<glm::vec4> inputs = airmassInputs(rays);
    const ShaderBenchmarkResult baseline = runAirmassKernel("airmassBaseline", inputs, rayCount, timing);
    const ShaderBenchmarkResult coherentBaseline = runAirmassKernel("airmassBaseline", inputs, rayCount, coherent);
    const ShaderBenchmarkResult throughputBaseline = runAirmassKernel("airmassBaseline", inputs, rayCount, throughput);
    std::vector<double> exact;
    for (const AirmassRay& ray : rays) exact.push_back(exactAirmass(ray));

    out << "airmass: " << rayCount << " rays (docs/airmass.md), shader: repeat " << timing.repeat << ", copies "
        << timing.copies << ", fastest of " << timing.runs << " dispatches, empty-loop baseline "
        << format("%.2f", baseline.seconds * 1e3) << " ms per dispatch subtracted; coherent: a work group per ray, repeat "
        << coherent.repeat << ", baseline " << format("%.2f", coherentBaseline.seconds * 1e3) << " ms; throughput: "
        << throughput.chains << " independent chains per invocation, baseline "
        << format("%.2f", throughputBaseline.seconds * 1e3) << " ms\n";
    out << "method               shader_ns  throughput_ns coherent_ns gpu_max_rel gpu_rms_rel gpu_nonfinite cpu32_max_rel cpu32_rms_rel "
           "cpu64_max_rel gpu_vs_cpu32 worst ray on the GPU: altitude_km cos_zenith t0 t1 H -> gpu exact\n";
    for (const AirmassMethod& method : airmassMethods()) {
        if (method.glslFunction.empty()) continue;
        const ShaderBenchmarkResult result = runAirmassKernel(method.glslFunction, inputs, rayCount, timing);
        const ShaderBenchmarkResult coherentResult = runAirmassKernel(method.glslFunction, inputs, rayCount, coherent);
        const ShaderBenchmarkResult throughputResult = runAirmassKernel(method.glslFunction, inputs, rayCount, throughput);
        std::vector<double> gpu, cpu32, cpu64;
        for (int i = 0; i < rayCount; ++i) {
            gpu.push_back(result.firstResults[size_t(i)].x);
            cpu32.push_back(evaluateAirmass(method, rays[size_t(i)], AirmassPrecision::Float32));
            cpu64.push_back(evaluateAirmass(method, rays[size_t(i)], AirmassPrecision::Float64));
        }
        const RelativeErrors gpuErrors = relativeErrors(gpu, exact, kAirmassRelativeErrorFloor);
        const RelativeErrors cpu32Errors = relativeErrors(cpu32, exact, kAirmassRelativeErrorFloor);
        const RelativeErrors cpu64Errors = relativeErrors(cpu64, exact, kAirmassRelativeErrorFloor);
        char line[512];
        std::snprintf(line, sizeof line, "%-20s %-10.2f %-13.2f %-11.2f %-11.3g %-11.3g %-13zu %-13.3g %-13.3g %-13.3g %-12.3g %s -> %.9g %.9g\n",
                      method.name.c_str(), nanosecondsPerEvaluation(result, baseline, rayCount, timing),
                      nanosecondsPerEvaluation(throughputResult, throughputBaseline, rayCount, throughput),
                      nanosecondsPerEvaluation(coherentResult, coherentBaseline, rayCount, coherent),
                      gpuErrors.maxRelativeError, gpuErrors.rmsRelativeError, gpuErrors.nonFiniteCount,
                      cpu32Errors.maxRelativeError, cpu32Errors.rmsRelativeError, cpu64Errors.maxRelativeError,
                      maxRelativeDifference(gpu, cpu32, exact, kAirmassRelativeErrorFloor),
                      describeRay(rays[gpuErrors.worstIndex]).c_str(), gpu[gpuErrors.worstIndex],
                      exact[gpuErrors.worstIndex]);
        out << line;
    }
}

namespace {

std::vector<glm::vec4> skyInputs(const std::vector<SkyView>& views)
{
    std::vector<glm::vec4> inputs;
    for (const SkyView& view : views) {
        inputs.emplace_back(glm::vec3(view.origin), float(view.tMax));
        inputs.emplace_back(glm::vec3(view.direction), 0.0f);
    }
    return inputs;
}

// SKY_BASELINE, SKY_NESTED or nothing (closed form) as `variant`.
ShaderBenchmarkResult runSkyKernel(const std::string& variant, const std::vector<glm::vec4>& inputs, int viewCount,
                                   const SkyAtmosphereParameters& atmosphere, const std::vector<SkyLight>& lights,
                                   const AccuracyReportSettings& settings, const ShaderBenchmarkSettings& timing)
{
    gl::ShaderSource source;
    if (!variant.empty()) source.defines.push_back(variant);
    source.defines.push_back("SKY_VIEW_STEPS " + std::to_string(settings.viewSteps));
    source.defines.push_back("SKY_LIGHT_STEPS " + std::to_string(settings.lightSteps));
    for (const char* module :
         {"physics/constants.glsl", "physics/atmosphere/airmass_common.glsl", "physics/atmosphere/airmass_chapman.glsl", "physics/atmosphere/sky.glsl"})
        source.modules.push_back(readShaderModule(module));
    source.modules.push_back({"sky_kernel.comp", kSkyKernel});
    return runShaderBenchmark(source, inputs, viewCount, timing, [&](gl::Program& program) {
        program.set("uSkyPlanetRadiusKm", float(atmosphere.planetRadiusKm));
        program.set("uSkyTopRadiusKm", float(atmosphere.topRadiusKm));
        program.set("uSkyScaleHeightKm", float(atmosphere.scaleHeightKm));
        program.set("uSkyRayleighScatteringPerKm", glm::vec3(atmosphere.rayleighScatteringPerKm));
        program.set("uSkyLightCount", int(lights.size()));
        for (size_t l = 0; l < lights.size(); ++l) {
            program.set("uSkyLightDirection[" + std::to_string(l) + "]", glm::vec3(lights[l].direction));
            program.set("uSkyLightIlluminanceLux[" + std::to_string(l) + "]", glm::vec3(lights[l].illuminanceLux));
        }
    });
}

} // namespace

void printSkyAccuracy(const AccuracyReportSettings& settings, std::ostream& out)
{
    const std::vector<SkyView> views = twilightViews(0.002);
    const int viewCount = int(views.size());
    const SkyAtmosphereParameters atmosphere;
    // Mixed: neighbouring invocations take different views. Coherent: a work group per view, as
    // neighbouring pixels of an image. The same number of pixels either way.
    ShaderBenchmarkSettings timing;
    timing.copies = 256 * copiesOf(settings);
    timing.runs = 5;
    ShaderBenchmarkSettings coherent;
    coherent.copies = 4 * copiesOf(settings);
    coherent.coherent = true;
    coherent.runs = 5;
    const std::vector<glm::vec4> inputs = skyInputs(views);

    // The reference's own error: its distance from a run with half the steps, over all light counts.
    double referenceSelfError = 0.0;
    std::vector<std::vector<SkyLight>> lightSets;
    std::vector<std::vector<glm::dvec3>> references;
    for (int lightCount : {1, 2, 4, 8}) {
        lightSets.push_back(twilightSuns(lightCount));
        references.push_back(skyRadiances(views, atmosphere, lightSets.back(), SkyLightMethod::NestedMarch,
                                          kSkyReferenceViewSteps, kSkyReferenceLightSteps, AirmassPrecision::Float64));
        const std::vector<glm::dvec3> half =
            skyRadiances(views, atmosphere, lightSets.back(), SkyLightMethod::NestedMarch, kSkyReferenceViewSteps / 2,
                         kSkyReferenceLightSteps / 2, AirmassPrecision::Float64);
        referenceSelfError = std::max(referenceSelfError, skyErrors(half, references.back()).maxRelativeError);
    }

    out << "sky: " << viewCount << " views from 2 m above the ground (azimuth 0-315 deg from the Sun, elevation 0-90 deg), "
        << "Sun positions 2-8 deg below the horizon, top of the air 100 km, H 8 km\n"
        << "reference: nested march in double with " << kSkyReferenceViewSteps << " x " << kSkyReferenceLightSteps
        << " steps (max distance from " << kSkyReferenceViewSteps / 2 << " x " << kSkyReferenceLightSteps / 2
        << " steps: " << format("%.2g", referenceSelfError) << "); errors relative per primary, floor "
        << format("%g", kSkyRadianceFloor) << " cd/m^2\n"
        << "shader: one view per invocation, " << viewCount * timing.copies
        << " pixels, fastest of " << timing.runs << " dispatches, empty-kernel baseline subtracted; ns per pixel mixed "
        << "(neighbours take different views) and coherent (a work group of 64 per view)\n";
    out << "lights method        M   K   ns_per_px  coherent_ns gpu_max_rel gpu_rms_rel cpu32_max_rel cpu64_max_rel "
           "gpu_vs_cpu32 worst view on the GPU (index)\n";
    for (size_t set = 0; set < lightSets.size(); ++set) {
        const std::vector<SkyLight>& lights = lightSets[set];
        const ShaderBenchmarkResult baseline =
            runSkyKernel("SKY_BASELINE", inputs, viewCount, atmosphere, lights, settings, timing);
        const ShaderBenchmarkResult coherentBaseline =
            runSkyKernel("SKY_BASELINE", inputs, viewCount, atmosphere, lights, settings, coherent);
        for (SkyLightMethod method : {SkyLightMethod::ClosedForm, SkyLightMethod::NestedMarch}) {
            const bool nested = method == SkyLightMethod::NestedMarch;
            const std::string variant = nested ? "SKY_NESTED" : "";
            const ShaderBenchmarkResult result =
                runSkyKernel(variant, inputs, viewCount, atmosphere, lights, settings, timing);
            const ShaderBenchmarkResult coherentResult =
                runSkyKernel(variant, inputs, viewCount, atmosphere, lights, settings, coherent);
            std::vector<glm::dvec3> gpu;
            for (const glm::vec4& value : result.firstResults) gpu.emplace_back(glm::vec3(value));
            const std::vector<glm::dvec3> cpu32 = skyRadiances(views, atmosphere, lights, method, settings.viewSteps,
                                                               settings.lightSteps, AirmassPrecision::Float32);
            const std::vector<glm::dvec3> cpu64 = skyRadiances(views, atmosphere, lights, method, settings.viewSteps,
                                                               settings.lightSteps, AirmassPrecision::Float64);
            const RelativeErrors gpuErrors = skyErrors(gpu, references[set]);
            std::vector<glm::dvec3> gpuMinusCpu32;
            for (size_t i = 0; i < gpu.size(); ++i) gpuMinusCpu32.push_back(references[set][i] + gpu[i] - cpu32[i]);
            char line[256];
            std::snprintf(line, sizeof line, "%-6zu %-13s %-3d %-3s %-10.1f %-11.1f %-11.3g %-11.3g %-13.3g %-13.3g %-12.3g %zu\n",
                          lights.size(), nested ? "nested-march" : "closed-form", settings.viewSteps,
                          nested ? std::to_string(settings.lightSteps).c_str() : "-",
                          nanosecondsPerEvaluation(result, baseline, viewCount, timing),
                          nanosecondsPerEvaluation(coherentResult, coherentBaseline, viewCount, coherent),
                          gpuErrors.maxRelativeError,
                          gpuErrors.rmsRelativeError, skyErrors(cpu32, references[set]).maxRelativeError,
                          skyErrors(cpu64, references[set]).maxRelativeError,
                          skyErrors(gpuMinusCpu32, references[set]).maxRelativeError, gpuErrors.worstIndex);
            out << line;
        }
    }
}

const std::vector<ShaderTable>& shaderTables()
{
    static const std::vector<ShaderTable> tables = {{"airmass", "the airmass methods", printAirmassAccuracy},
                                                    {"sky", "the several-lights sky", printSkyAccuracy}};
    return tables;
}

} // namespace aurorawall::physics::atmosphere
