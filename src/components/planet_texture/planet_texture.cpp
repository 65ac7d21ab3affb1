#include "components/planet_texture/planet_texture.h"

#include "components/planet_texture/night_lights.h"
#include "scene/scene.h"
#include "components/roles/names.h"

#include <filesystem>

namespace aurorawall::components::planet_texture {

namespace {

class Renderer : public scene::ComponentRenderer {
public:
    explicit Renderer(const Settings& s) : lights_(s) {}
    std::string precomputationLog() const override { return lights_.summary(); }
    void setFrame(gl::Program&, const cluster::FrameState&) override {}
    void bind(gl::Program& program) const override { lights_.bind(program); }

private:
    NightLights lights_;
};

class PlanetTexture : public scene::ComponentWithRenderer<Settings, Renderer> {
public:
    std::vector<std::string> needs() const override { return {roles::kGround}; }
    void read(const config::TableReader& t, scene::Scene&, scene::ComponentSettings& settings) const override
    {
        auto& s = dynamic_cast<Settings&>(settings);
        // The default image is optional (the ground stays uniform without it); one the file names is not.
        if (t.has("night_image")) {
            s.nightImage = t.string("night_image", s.nightImage);
            if (!std::filesystem::is_regular_file(s.nightImage))
                t.fail("night_image", s.nightImage + ": " +
                                          (std::filesystem::exists(s.nightImage) ? "not a file" : "no such image file"));
        }
        s.nightLightsRadiance = t.number("night_lights_cd_m2", 0.0, 1e6, s.nightLightsRadiance);
    }
    std::vector<std::string> shaderModules() const override
    {
        return {"components/planet_texture/night_lights.glsl"};
    }
    std::string shaderShadeCall() const override { return "shadeNightLights(ray)"; }
    // Lights on the ground: after the ground surface (it needs the planet).
    scene::Shell shell() const override { return scene::Shell::Ground; }
    double reachKm(const scene::Scene&) const override { return 0.0; } // on the ground
    std::string notInReferenceBecause() const override
    {
        return "planet_texture is an image lookup, not a model the reference evaluates";
    }
};

} // namespace

const scene::Component& component()
{
    static const PlanetTexture instance;
    return instance;
}

} // namespace aurorawall::components::planet_texture
