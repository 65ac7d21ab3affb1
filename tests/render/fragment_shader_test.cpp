#include "render/fragment_shader.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <algorithm>

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
    s.components = {scene::Component::Planet, scene::Component::Stars};
    const gl::ShaderSource source = render::fragmentShaderSource(s, kShaders);
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
    const scene::Scene s = scene::loadScene(std::string(AURORAWALL_SOURCE_DIR) + "/config/scenes/substorm.toml");
    const std::vector<std::string> names = render::fragmentModuleNames(s);
    EXPECT_TRUE(contains(names, "scene/aurora_curtains.glsl"));
    EXPECT_TRUE(contains(names, "scene/atmosphere.glsl"));
    EXPECT_EQ(names.back(), "render/main.frag");
}

TEST(FragmentShader, MissingShaderFolderNamesTheFile)
{
    scene::Scene s;
    s.components = {scene::Component::Planet};
    try {
        render::fragmentShaderSource(s, "/nonexistent/shaders");
        FAIL() << "no error";
    } catch (const std::exception& e) {
        EXPECT_EQ(std::string(e.what()).rfind("/nonexistent/shaders/render/ray_sphere.glsl: ", 0), 0u) << e.what();
    }
}
