#include "components/sky/sky.h"

#include "physics/constants.h"
#include "gl/shader_program.h"
#include "scene/scene.h"
#include "components/roles/lower_atmosphere.h"

#include <cmath>

namespace aurorawall::components::sky {

namespace {

constexpr int kMaxLights = 8; // SKY_MAX_LIGHTS of shaders/physics/atmosphere/sky.glsl

class Renderer : public scene::ComponentRenderer {
public:
    explicit Renderer(const Settings& s) : s_(s) {}
    void setFrame(gl::Program& program, const cluster::FrameState&) override
    {
        program.set("uSkyViewSteps", s_.viewSteps);
        program.set("uSkyLightMethod", s_.nestedMarch ? 1 : 0); // SKY_LIGHT_NESTED_MARCH : SKY_LIGHT_CLOSED_FORM
        program.set("uSkyLightSteps", s_.lightSteps);
        program.set("uSkyLightCount", static_cast<int>(s_.lights.size()));
        for (size_t i = 0; i < s_.lights.size(); ++i) {
            const std::string index = "[" + std::to_string(i) + "]";
            program.set("uSkyLightDirection" + index, glm::vec3(s_.lights[i].direction));
            program.set("uSkyLightIlluminanceLux" + index, glm::vec3(s_.lights[i].illuminanceLux));
        }
    }

private:
    const Settings& s_;
};

// A light is given as seen from a site: where it stands in that sky (elevation above the
// horizon, azimuth clockwise from north), and its illuminance above the atmosphere.
Light readLight(const config::TableReader& t)
{
    Light l;
    const double lat = t.number("site_latitude_deg", -90, 90), lon = t.number("site_longitude_deg", -360, 360);
    l.direction = scene::directionInSky(lat, lon, t.number("elevation_deg", -90, 90), t.number("azimuth_deg", -360, 360));
    l.illuminanceLux = glm::dvec3(t.number("illuminance_lux", 0.0, 1e7, 1.28e5));
    t.rejectUnknownKeys();
    return l;
}

class Sky : public scene::ComponentWithRenderer<Settings, Renderer> {
public:
    std::vector<std::string> needs() const override { return {roles::kLowerAtmosphere}; }
    void read(const config::TableReader& t, scene::Scene&, scene::ComponentSettings& settings) const override
    {
        auto& s = dynamic_cast<Settings&>(settings);
        s.viewSteps = t.integer("view_steps", 1, 1024, s.viewSteps);
        s.nestedMarch = t.choice("light_method", {"closed-form", "nested-march"}, s.nestedMarch) == 1;
        s.lightSteps = t.integer("light_steps", 1, 1024, s.lightSteps);
        if (t.has("light")) {
            s.lights.clear();
            for (const config::TableReader& l : t.arrayOfTables("light"))
                s.lights.push_back(readLight(l));
        }
        if (s.lights.size() > kMaxLights)
            t.fail("light", "at most " + std::to_string(kMaxLights) + " lights");
    }
    std::vector<std::string> shaderModules() const override
    {
        return {"physics/atmosphere/sky.glsl", "components/sky/sky.glsl"};
    }
    std::string shaderShadeCall() const override { return "shadeSky(ray)"; }
    // The light the lower atmosphere scatters: after its extinction (it needs the atmosphere).
    scene::Shell shell() const override { return scene::Shell::LowerAtmosphere; }
    // It scatters within the lower atmosphere's air.
    double reachKm(const scene::Scene& scene) const override
    {
        const auto air = roles::lowerAir(scene);
        return air ? air->topKm : 0.0;
    }
    std::string notInReferenceBecause() const override
    {
        return "the sky has its own reference (aurorawall accuracy --sky), not this one";
    }
};

} // namespace

const scene::Component& component()
{
    static const Sky instance;
    return instance;
}

} // namespace aurorawall::components::sky
