#include "components/atmosphere/atmosphere.h"

#include "physics/atmosphere/airmass.h"
#include "physics/atmosphere/airmass_exact.h"
#include "gl/shader_program.h"
#include "scene/ray_steps.h"
#include "scene/scene.h"
#include "components/roles/lower_atmosphere.h"
#include "components/roles/names.h"

namespace aurorawall::components::atmosphere {

namespace {

class Renderer : public scene::ComponentRenderer {
public:
    explicit Renderer(const Settings& s) : s_(s) {}
    void setFrame(gl::Program& program, const cluster::FrameState&) override
    {
        program.set("uAtmosphereTopKm", static_cast<float>(s_.topKm));
        program.set("uScaleHeightKm", static_cast<float>(s_.scaleHeightKm));
        program.set("uExtinctionPerKm", glm::vec3(s_.extinctionPerKm));
        program.set("uSkyGlow", glm::vec3(s_.skyGlow));
    }

private:
    const Settings& s_;
};

// shadeAtmosphere with the exact airmass (adaptive Gauss-Kronrod) instead of the closed form, or, with
// shaderSteps, the shader's closed form in double.
class Reference : public scene::ReferenceShader {
public:
    Reference(const Settings& s, double radiusKm, bool shaderSteps)
        : s_(s), radiusKm_(radiusKm),
          closedForm_(shaderSteps ? physics::atmosphere::findAirmassMethod(physics::atmosphere::kDefaultAirmassMethod)->float64
                                  : nullptr)
    {
    }
    scene::f64::Ray shade(scene::f64::Ray ray) const override
    {
        ray.lowerAtmosphere = scene::f64::lowerShellSegment(ray, radiusKm_, s_.topKm);
        if (ray.lowerAtmosphere.x < ray.lowerAtmosphere.y) {
            const double airmass =
                closedForm_ ? closedForm_(ray.origin, ray.direction, ray.lowerAtmosphere.x, ray.lowerAtmosphere.y,
                                          s_.scaleHeightKm, radiusKm_)
                            : physics::atmosphere::exactAirmass(ray.origin, ray.direction, ray.lowerAtmosphere.x,
                                                                ray.lowerAtmosphere.y, s_.scaleHeightKm, radiusKm_);
            ray.transmittance = glm::exp(-s_.extinctionPerKm * airmass);
            ray.radiance += s_.skyGlow * (1.0 - ray.transmittance);
        }
        return ray;
    }

private:
    const Settings& s_;
    double radiusKm_;
    double (*closedForm_)(glm::dvec3, glm::dvec3, double, double, double, double); // null: the exact airmass
};

class Atmosphere : public scene::ComponentWithRenderer<Settings, Renderer>, public roles::LowerAtmosphereProvider {
public:
    std::vector<std::string> needs() const override { return {roles::kGround}; }
    std::vector<std::string> provides() const override { return {roles::kLowerAtmosphere}; }
    void read(const config::TableReader& t, scene::Scene&, scene::ComponentSettings& settings) const override
    {
        auto& s = dynamic_cast<Settings&>(settings);
        s.topKm = t.number("top_km", 1.0, 1000.0, s.topKm);
        s.scaleHeightKm = t.number("scale_height_km", 0.1, 1000.0, s.scaleHeightKm);
        s.extinctionPerKm = t.vector3("extinction_per_km", 0.0, 1e3, s.extinctionPerKm);
        s.skyGlow = t.vector3("sky_glow_cd_m2", 0.0, 1e6, s.skyGlow);
    }
    std::vector<std::string> shaderModules() const override
    {
        return {"physics/atmosphere/airmass_common.glsl", "physics/atmosphere/airmass_chapman.glsl",
                "components/atmosphere/atmosphere.glsl"};
    }
    std::string shaderShadeCall() const override { return "shadeAtmosphere(ray)"; }
    scene::Shell shell() const override { return scene::Shell::LowerAtmosphere; }
    double reachKm(const scene::Scene& scene) const override { return scene.settings<Settings>().topKm; }
    std::unique_ptr<scene::ReferenceShader> makeReference(const scene::Scene& scene,
                                                          const scene::ReferenceContext& context) const override
    {
        return std::make_unique<Reference>(scene.settings<Settings>(), scene.planetRadiusKm, context.shaderSteps);
    }
    roles::LowerAir air(const scene::Scene& scene) const override
    {
        const Settings& s = scene.settings<Settings>();
        return {s.topKm, s.scaleHeightKm, s.extinctionPerKm, std::string(Settings::kComponent) + ".top_km"};
    }
};

} // namespace

const scene::Component& component()
{
    static const Atmosphere instance;
    return instance;
}

} // namespace aurorawall::components::atmosphere
