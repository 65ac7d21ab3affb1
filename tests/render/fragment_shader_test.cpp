#include "render/fragment_shader.h"
#include "render/scene_uniforms.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

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

TEST(SceneUniforms, FoldPhaseStaysExactAtHugeTimes)
{
    // At t = 1e9 s the phase is reduced in double on the CPU: it is in [0, 2 pi) and equals
    // the exact value computed with long double.
    scene::Scene s = scene::loadScene(std::string(AURORAWALL_SOURCE_DIR) + "/config/scenes/substorm.toml");
    for (double t : {0.0, 12.5, 1e9, 1e9 + 0.5}) {
        const render::CurtainUniforms u = render::curtainUniforms(s, t);
        ASSERT_EQ(u.folds.size(), s.aurora.curtains.size());
        for (size_t c = 0; c < u.folds.size(); ++c) {
            const scene::Curtain& curtain = s.aurora.curtains[c];
            const long double cycles = (long double)curtain.driftKmPerS * t / curtain.foldWavelengthKm;
            long double exact = -2.0L * M_PIl * (cycles - std::floor(cycles));
            exact = exact < 0 ? exact + 2.0L * M_PIl : exact;
            EXPECT_GE(u.folds[c].y, 0.0f);
            EXPECT_LT(u.folds[c].y, 6.2832f);
            const double diff = std::remainder(double(u.folds[c].y - exact), 2.0 * M_PI);
            EXPECT_NEAR(diff, 0.0, 1e-5) << "t=" << t;
        }
    }
}
