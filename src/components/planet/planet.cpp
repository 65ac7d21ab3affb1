#include "components/planet/planet.h"

#include "gl/shader_program.h"
#include "scene/ray_steps.h"
#include "scene/scene.h"
#include "components/roles/names.h"

namespace aurorawall::components::planet {

namespace {

class Renderer : public scene::ComponentRenderer {
public:
    Renderer(const Settings& s, double radiusKm) : s_(s), radiusKm_(radiusKm) {}
    void setFrame(gl::Program& program, const cluster::FrameState& frame) override
    {
        program.set("uPlanetRadiusKm", static_cast<float>(radiusKm_));
        // From double: in float the altitude of a camera near the ground would move in 0.5 m steps.
        program.set("uCameraAltitudeKm", static_cast<float>(scene::altitudeKm(frame.cameraPositionKm, radiusKm_)));
        program.set("uPlanetRadiance", glm::vec3(s_.surfaceRadiance));
    }

private:
    const Settings& s_;
    double radiusKm_;
};

class Reference : public scene::ReferenceShader {
public:
    Reference(const Settings& s, double radiusKm) : s_(s), radiusKm_(radiusKm) {}
    scene::f64::Ray bound(scene::f64::Ray ray) const override
    {
        return scene::f64::boundByGround(ray, radiusKm_, scene::altitudeKm(ray.origin, radiusKm_));
    }
    scene::f64::Ray shade(scene::f64::Ray ray) const override
    {
        if (ray.groundT >= 0.0)
            ray.radiance += s_.surfaceRadiance * ray.transmittance;
        return ray;
    }

private:
    const Settings& s_;
    double radiusKm_;
};

class Planet : public scene::ComponentWith<Settings> {
public:
    std::vector<std::string> provides() const override { return {roles::kGround}; }
    void read(const config::TableReader& t, scene::Scene& scene, scene::ComponentSettings& settings) const override
    {
        auto& s = dynamic_cast<Settings&>(settings);
        scene.planetRadiusKm = t.number("radius_km", 1.0, 1e6, scene.planetRadiusKm);
        s.surfaceRadiance = t.vector3("surface_radiance_cd_m2", 0.0, 1e6, s.surfaceRadiance);
    }
    std::vector<std::string> shaderModules() const override { return {"components/planet/planet.glsl"}; }
    std::string shaderGeometryCall() const override { return "boundByGround(ray, uPlanetRadiusKm, rayStartAltitude(ray))"; }
    std::string shaderShadeCall() const override { return "shadeGround(ray)"; }
    scene::Shell shell() const override { return scene::Shell::Ground; }
    double reachKm(const scene::Scene&) const override { return 0.0; } // the ground itself
    std::unique_ptr<scene::ComponentRenderer> makeRenderer(const scene::Scene& scene,
                                                           const scene::FindRenderer&) const override
    {
        return std::make_unique<Renderer>(scene.settings<Settings>(), scene.planetRadiusKm);
    }
    std::unique_ptr<scene::ReferenceShader> makeReference(const scene::Scene& scene,
                                                          const scene::ReferenceContext&) const override
    {
        return std::make_unique<Reference>(scene.settings<Settings>(), scene.planetRadiusKm);
    }
};

} // namespace

const scene::Component& component()
{
    static const Planet instance;
    return instance;
}

} // namespace aurorawall::components::planet
