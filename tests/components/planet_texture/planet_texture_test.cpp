// The night lights' image: the default one is optional (the ground stays uniform without it), one a
// scene file names must exist, and its error names the file, the line and the key.
#include "components/planet_texture/planet_texture.h"
#include "components/registry.h"
#include "scene/load_error.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

using namespace aurorawall;
using test::loadErrorOfText;
using test::temporarySceneFile;

namespace {

const std::string kHead = "[scene]\nname = \"lights\"\ncomponents = [\"planet\", \"planet_texture\"]\n"
                          "[camera]\nlatitude_deg = 65.0\nlongitude_deg = 20.0\naltitude_km = 400.0\n"
                          "heading_deg = 0.0\nelevation_deg = -90.0\n";

} // namespace

TEST(PlanetTexture, DefaultImageIsOptional)
{
    const auto s = components::loadScene(temporarySceneFile("default.toml", kHead))
                       .settings<components::planet_texture::Settings>();
    EXPECT_EQ(s.nightImage, components::planet_texture::Settings().nightImage);
}

TEST(PlanetTexture, NamedImageMustExist)
{
    const std::string missing = ::testing::TempDir() + "no-such-night.jpg";
    const std::string file = temporarySceneFile("missing.toml", kHead + "[planet_texture]\nnight_image = \"" + missing + "\"\n");
    EXPECT_EQ(test::loadError(file), file + ":11: planet_texture.night_image: " + missing + ": no such image file");
    const std::string folder = ::testing::TempDir();
    const std::string named = temporarySceneFile("folder.toml", kHead + "[planet_texture]\nnight_image = \"" + folder + "\"\n");
    EXPECT_EQ(test::loadError(named), named + ":11: planet_texture.night_image: " + folder + ": not a file");

    const std::string present = ::testing::TempDir() + "night.jpg";
    std::ofstream(present) << "stand-in: the scene loader checks only that the file is there";
    const auto s = components::loadScene(temporarySceneFile("present.toml", kHead + "[planet_texture]\nnight_image = \"" +
                                                                                present + "\"\nnight_lights_cd_m2 = 1e-3\n"))
                       .settings<components::planet_texture::Settings>();
    EXPECT_EQ(s.nightImage, present);
    EXPECT_EQ(s.nightLightsRadiance, 1e-3);
}
