#include "components/stars/stars.h"

#include "gl/shader_program.h"
#include "scene/scene.h"

namespace aurorawall::components::stars {

namespace {

class Renderer : public scene::ComponentRenderer {
public:
    explicit Renderer(const Settings& s) : s_(s) {}
    void setFrame(gl::Program& program, const cluster::FrameState&) override
    {
        program.set("uStarDensity", static_cast<float>(s_.density));
        program.set("uStarBrightness", static_cast<float>(s_.brightnessCdM2));
    }

private:
    const Settings& s_;
};

class Stars : public scene::ComponentWithRenderer<Settings, Renderer> {
public:
    void read(const config::TableReader& t, scene::Scene&, scene::ComponentSettings& settings) const override
    {
        auto& s = dynamic_cast<Settings&>(settings);
        s.density = t.number("density", 0.0, 1.0, s.density);
        s.brightnessCdM2 = t.number("brightness_cd_m2", 0.0, 1e6, s.brightnessCdM2);
    }
    std::vector<std::string> shaderModules() const override { return {"components/stars/stars.glsl"}; }
    std::string shaderShadeCall() const override { return "shadeStars(ray)"; }
    scene::Shell shell() const override { return scene::Shell::Space; }
    double reachKm(const scene::Scene&) const override { return 0.0; } // at infinity
    std::string notInReferenceBecause() const override
    {
        return "stars are a hash of float direction bits, not a model the reference converges to";
    }
};

} // namespace

const scene::Component& component()
{
    static const Stars instance;
    return instance;
}

} // namespace aurorawall::components::stars
