#include "components/airglow/airglow.h"

#include "physics/atmosphere/airmass_exact.h"
#include "physics/colour.h"
#include "physics/emission_lines.h"
#include "gl/shader_program.h"
#include "scene/ray_steps.h"
#include "scene/scene.h"
#include "components/roles/lower_atmosphere.h"
#include "components/roles/names.h"

#include <algorithm>
#include <cmath>

namespace aurorawall::components::airglow {

namespace {

// Layers are cut off where the upper exponential has fallen by e^-40 (AIRGLOW_TOP_SCALE_HEIGHTS).
constexpr double kTopScaleHeights = 40.0;

class Renderer : public scene::ComponentRenderer {
public:
    explicit Renderer(const Settings& s)
    {
        for (const Layer& l : s.layers) {
            const LayerProfile p = layerProfile(l);
            layers_.emplace_back(p.baseKm, p.upperScaleHeightKm, p.lowerScaleHeightKm, p.rayleighPerKm);
            rgb_.emplace_back(physics::lineLinearSrgbPerRayleigh(wavelengthNm(l.line), cieXyz(l.line)));
        }
    }
    void setFrame(gl::Program& program, const cluster::FrameState&) override
    {
        program.set("uAirglowLayerCount", static_cast<int>(layers_.size()));
        for (size_t i = 0; i < layers_.size(); ++i) {
            const std::string index = "[" + std::to_string(i) + "]";
            program.set("uAirglowLayer" + index, layers_[i]);
            program.set("uAirglowRgbPerRayleigh" + index, rgb_[i]);
        }
    }

private:
    std::vector<glm::vec4> layers_;
    std::vector<glm::vec3> rgb_;
};

// shadeAirglow in double with the exact airmass (adaptive Gauss-Kronrod) of both exponentials.
class Reference : public scene::ReferenceShader {
public:
    Reference(const Settings& s, double radiusKm) : radiusKm_(radiusKm)
    {
        for (const Layer& l : s.layers) {
            profiles_.push_back(layerProfile(l));
            rgb_.push_back(physics::lineLinearSrgbPerRayleigh(wavelengthNm(l.line), cieXyz(l.line)));
        }
    }
    scene::f64::Ray shade(scene::f64::Ray ray) const override
    {
        for (size_t i = 0; i < profiles_.size(); ++i) {
            const LayerProfile& p = profiles_[i];
            const double base = p.baseKm, top = base + kTopScaleHeights * p.upperScaleHeightKm;
            const scene::f64::ShellSegments shell = scene::f64::rayShell(ray.origin, ray.direction, radiusKm_ + base,
                                                           ray.altitude - base, radiusKm_ + top, ray.altitude - top,
                                                           ray.end);
            for (const glm::dvec2 part : {shell.first, shell.second}) {
                if (!(part.x < part.y))
                    continue;
                const double upper = physics::atmosphere::exactAirmass(ray.origin, ray.direction, part.x, part.y, p.upperScaleHeightKm,
                                                  radiusKm_ + base);
                const double lower = physics::atmosphere::exactAirmass(ray.origin, ray.direction, part.x, part.y, p.lowerScaleHeightKm,
                                                  radiusKm_ + base);
                ray.radiance += rgb_[i] * scene::f64::transmittanceTo(ray, part) * (p.rayleighPerKm * (upper - lower));
            }
        }
        return ray;
    }

private:
    double radiusKm_;
    std::vector<LayerProfile> profiles_;
    std::vector<glm::dvec3> rgb_;
};

Layer readLayer(const config::TableReader& t)
{
    Layer l;
    if (!t.has("line"))
        t.fail("line", "missing: green (557.7 nm), sodium (589.3 nm) or red (630.0 nm)");
    l.line = static_cast<Line>(t.choice("line", {"green", "sodium", "red"}, 0));
    l.zenithRayleigh = t.number("zenith_rayleigh", 0.0, 1e7);
    l.peakKm = t.number("peak_km", 1.0, 5000.0);
    l.fwhmKm = t.number("fwhm_km", 0.1, 1000.0);
    t.rejectUnknownKeys();
    return l;
}

class Airglow : public scene::ComponentWithRenderer<Settings, Renderer> {
public:
    std::vector<std::string> needs() const override { return {roles::kGround}; }
    void read(const config::TableReader& t, scene::Scene& scene, scene::ComponentSettings& settings) const override
    {
        auto& s = dynamic_cast<Settings&>(settings);
        if (t.has("layer")) {
            s.layers.clear();
            for (const config::TableReader& l : t.arrayOfTables("layer"))
                s.layers.push_back(readLayer(l));
        }
        if (s.layers.size() > Settings::kMaxLayers)
            t.fail("layer", "at most " + std::to_string(Settings::kMaxLayers) + " layers");
        // The layers are composited behind or in front of the lower atmosphere as a whole.
        if (const auto air = roles::lowerAir(scene))
            for (const Layer& l : s.layers)
                if (layerProfile(l).baseKm < air->topKm)
                    t.fail("layer", "a layer's base (peak - 0.39 fwhm) must not be below " + air->topKey);
    }
    std::vector<std::string> shaderModules() const override
    {
        // The airmass modules may also come from the lower atmosphere's provider: each is included once.
        return {"physics/atmosphere/airmass_common.glsl", "physics/atmosphere/airmass_chapman.glsl",
                "components/airglow/airglow_layer.glsl", "components/airglow/airglow.glsl"};
    }
    std::string shaderShadeCall() const override { return "shadeAirglow(ray)"; }
    scene::Shell shell() const override { return scene::Shell::EmittingLayers; }
    // The top of the highest layer: its base plus the upper exponential's kTopScaleHeights.
    double reachKm(const scene::Scene& scene) const override
    {
        double top = 0.0;
        for (const Layer& l : scene.settings<Settings>().layers) {
            const LayerProfile p = layerProfile(l);
            top = std::max(top, p.baseKm + kTopScaleHeights * p.upperScaleHeightKm);
        }
        return top;
    }
    std::unique_ptr<scene::ReferenceShader> makeReference(const scene::Scene& scene,
                                                          const scene::ReferenceContext&) const override
    {
        return std::make_unique<Reference>(scene.settings<Settings>(), scene.planetRadiusKm);
    }
};

} // namespace

LayerProfile layerProfile(const Layer& layer)
{
    const double root = std::sqrt(0.5);
    LayerProfile p;
    p.upperScaleHeightKm = layer.fwhmKm / std::log((1.0 + root) / (1.0 - root));
    p.lowerScaleHeightKm = 0.5 * p.upperScaleHeightKm;
    p.baseKm = layer.peakKm - p.upperScaleHeightKm * std::log(2.0);
    p.rayleighPerKm = layer.zenithRayleigh / (p.upperScaleHeightKm - p.lowerScaleHeightKm);
    return p;
}

double volumeEmission(const LayerProfile& p, double altitudeKm)
{
    const double x = altitudeKm - p.baseKm;
    if (x < 0.0)
        return 0.0;
    return p.rayleighPerKm * (std::exp(-x / p.upperScaleHeightKm) - std::exp(-x / p.lowerScaleHeightKm));
}

double wavelengthNm(Line line)
{
    switch (line) {
    case Line::Green5577: return physics::lineInfo(physics::EmissionLine::Green5577).wavelengthNm;
    case Line::Sodium5893: return 589.3; // the D2/D1 doublet 589.0/589.6 nm, its mean
    case Line::Red6300: return physics::lineInfo(physics::EmissionLine::Red6300).wavelengthNm;
    }
    return 0.0;
}

glm::dvec3 cieXyz(Line line)
{
    switch (line) {
    case Line::Green5577: return physics::lineInfo(physics::EmissionLine::Green5577).cieXyz;
    // CIE 1931 2° at 589.3 nm, linear between the 5 nm table's 585 nm (0.9786, 0.8163, 0.0014)
    // and 590 nm (1.0263, 0.7570, 0.0011).
    case Line::Sodium5893: return glm::mix(glm::dvec3(0.9786, 0.8163, 0.0014), glm::dvec3(1.0263, 0.7570, 0.0011), 0.86);
    case Line::Red6300: return physics::lineInfo(physics::EmissionLine::Red6300).cieXyz;
    }
    return glm::dvec3(0.0);
}

const scene::Component& component()
{
    static const Airglow instance;
    return instance;
}

} // namespace aurorawall::components::airglow
