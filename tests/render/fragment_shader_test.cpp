#include "render/march_shader.h"
#include "components/planet/planet.h"
#include "components/registry.h"
#include "components/stars/stars.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>

using namespace aurorawall;

namespace {
const std::string kShaders = std::string(AURORAWALL_SOURCE_DIR) + "/shaders";

bool contains(const std::vector<std::string>& v, const std::string& x)
{
    return std::find(v.begin(), v.end(), x) != v.end();
}
} // namespace

TEST(FragmentShader, CompilesOnlyTheListedComponents)
{
    scene::Scene s;
    s.add(components::planet::component());
    s.add(components::stars::component());
    const gl::ShaderSource source = render::marchShaderSource(s, kShaders);
    EXPECT_TRUE(contains(source.defines, "HAS_PLANET"));
    EXPECT_TRUE(contains(source.defines, "HAS_STARS"));
    EXPECT_FALSE(contains(source.defines, "HAS_AURORA"));
    EXPECT_FALSE(contains(source.defines, "HAS_ATMOSPHERE"));
    for (const gl::ShaderModule& m : source.modules) {
        EXPECT_EQ(m.file.find("aurora"), std::string::npos) << m.file;
        EXPECT_EQ(m.text.find("uniform float uAuroraStepKm"), std::string::npos) << m.file;
    }
}

TEST(FragmentShader, FullSceneHasEveryModule)
{
    const scene::Scene s = components::loadScene(std::string(AURORAWALL_SOURCE_DIR) + "/config/scenes/substorm.toml");
    const std::vector<std::string> names = render::marchModuleNames(s);
    EXPECT_TRUE(contains(names, "components/aurora/aurora_curtains.glsl"));
    EXPECT_TRUE(contains(names, "components/atmosphere/atmosphere.glsl"));
    EXPECT_EQ(names.back(), "render/main.frag");
    EXPECT_EQ(render::marchModuleNames(s, render::MarchStage::Compute).back(), "render/main.comp");
}

TEST(FragmentShader, MissingShaderFolderNamesTheFile)
{
    scene::Scene s;
    s.add(components::planet::component());
    try {
        render::marchShaderSource(s, "/nonexistent/shaders");
        FAIL() << "no error";
    } catch (const std::exception& e) {
        EXPECT_EQ(std::string(e.what()).rfind("/nonexistent/shaders/physics/constants.glsl: ", 0), 0u) << e.what();
    }
}

TEST(FragmentShader, ShadeRayCallsTheListedComponentsInCompositingOrder)
{
    // Registry order planet, atmosphere, aurora, stars; compositing order by shell: the lower
    // atmosphere, the emitting structures, the ground, space, after the planet's geometry step.
    const scene::Scene s = components::loadScene(std::string(AURORAWALL_SOURCE_DIR) + "/config/scenes/quiet-arc.toml");
    const std::string code = render::compositingSource(s);
    const size_t ground = code.find("boundByGround("), atmosphere = code.find("shadeAtmosphere("),
                 aurora = code.find("shadeAurora("), planet = code.find("shadeGround("), stars = code.find("shadeStars(");
    ASSERT_NE(ground, std::string::npos) << code;
    ASSERT_NE(stars, std::string::npos) << code;
    EXPECT_LT(ground, atmosphere);
    EXPECT_LT(atmosphere, aurora);
    EXPECT_LT(aurora, planet);
    EXPECT_LT(planet, stars);
    EXPECT_EQ(code.find("shadeSky("), std::string::npos) << code;
    EXPECT_EQ(code.find("shadeNightLights("), std::string::npos) << code;
}

// The glory's modules, uniforms and steps are in the shader of a scene that lists it, between the
// aurora and the ground, and in no other; a scene without it precomputes no table either (its
// renderer is made only for listed components).
TEST(FragmentShader, GloryOnlyWhereListed)
{
    const std::string dir = std::string(AURORAWALL_SOURCE_DIR) + "/config/scenes/";
    const scene::Scene lunar = components::loadScene(dir + "lunar-glory.toml");
    const std::string code = render::compositingSource(lunar);
    EXPECT_LT(code.find("boundByGround("), code.find("boundByCloudDeck("));
    EXPECT_LT(code.find("shadeAurora("), code.find("shadeGlory("));
    EXPECT_LT(code.find("shadeGlory("), code.find("shadeGround("));
    EXPECT_TRUE(contains(render::marchModuleNames(lunar), "components/glory/glory.glsl"));

    for (const char* file : {"quiet-arc.toml", "substorm.toml", "airglow-limb.toml"}) {
        const scene::Scene s = components::loadScene(dir + file);
        const gl::ShaderSource source = render::marchShaderSource(s, kShaders);
        EXPECT_FALSE(contains(source.defines, "HAS_GLORY")) << file;
        for (const gl::ShaderModule& m : source.modules) {
            EXPECT_EQ(m.file.find("glory"), std::string::npos) << file << ": " << m.file;
            EXPECT_EQ(m.text.find("uGlory"), std::string::npos) << file << ": " << m.file;
        }
    }
}

// The plasma adds no module of its own: its frames reach the aurora's curtain profile under
// HAS_CURTAIN_DETAIL, the define of the role it provides, which only a scene listing a provider (the
// plasma or fluid_detail) defines; HAS_PLASMA only a scene listing it (and its renderer, the
// simulation, is made only for listed components); such a scene does not list fluid_detail.
TEST(FragmentShader, PlasmaOnlyWhereListed)
{
    const std::string dir = std::string(AURORAWALL_SOURCE_DIR) + "/config/scenes/";
    const gl::ShaderSource curls =
        render::marchShaderSource(components::loadScene(dir + "plasma-curls.toml"), kShaders);
    EXPECT_TRUE(contains(curls.defines, "HAS_PLASMA"));
    EXPECT_TRUE(contains(curls.defines, "HAS_CURTAIN_DETAIL"));
    EXPECT_FALSE(contains(curls.defines, "HAS_FLUID_DETAIL"));
    for (const char* file : {"quiet-arc.toml", "substorm.toml", "airglow-limb.toml", "lunar-glory.toml"}) {
        const scene::Scene s = components::loadScene(dir + file);
        const gl::ShaderSource source = render::marchShaderSource(s, kShaders);
        EXPECT_FALSE(contains(source.defines, "HAS_PLASMA")) << file;
        EXPECT_EQ(contains(source.defines, "HAS_CURTAIN_DETAIL"), s.has("fluid_detail")) << file;
        for (const gl::ShaderModule& m : source.modules)
            EXPECT_EQ(m.file.find("components/plasma"), std::string::npos) << file << ": " << m.file;
    }
}

// Every shipped scene's shading steps run in the order they ran in when the order was a number per
// component (10 atmosphere, 20 sky, 30 airglow, 40 aurora, 41 plasma box, 58 cloud deck, 60 ground,
// 61 ground lights, 70 stars): the declared shells and their rule give the same images, bit for bit.
TEST(FragmentShader, ShippedScenesKeepTheOrderOfTheirShadingSteps)
{
    const std::vector<std::string> former = {"shadeAtmosphere", "shadeSky",   "shadeAirglow",
                                             "shadeAurora",     "shadePlasmaBox", "shadeGlory",
                                             "shadeGround",     "shadeNightLights", "shadeStars"};
    int scenes = 0;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(AURORAWALL_SOURCE_DIR) + "/config/scenes")) {
        if (entry.path().extension() != ".toml")
            continue;
        ++scenes;
        const std::string code = render::compositingSource(components::loadScene(entry.path().string()));
        const std::regex call(R"(ray = (shade\w+)\()");
        std::vector<std::string> calls;
        for (auto m = std::sregex_iterator(code.begin(), code.end(), call); m != std::sregex_iterator(); ++m)
            calls.push_back((*m)[1]);
        ASSERT_FALSE(calls.empty()) << entry.path();
        size_t last = 0;
        for (const std::string& c : calls) {
            const auto at = std::find(former.begin(), former.end(), c);
            ASSERT_NE(at, former.end()) << entry.path() << ": " << c;
            const size_t index = static_cast<size_t>(at - former.begin());
            EXPECT_GE(index, last) << entry.path() << ":\n" << code;
            last = index;
        }
    }
    EXPECT_EQ(scenes, 16);
}
