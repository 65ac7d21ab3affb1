#include "physics/constants.h"
#include "common/input_error.h"
#include "components/airglow/airglow.h"
#include "components/aurora/aurora.h"
#include "components/fluid_detail/fluid_detail.h"
#include "components/registry.h"
#include "config/toml_reader.h"
#include "scene/scene.h"
#include "load_error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

using namespace aurorawall;

namespace {

const std::string kData = SCENE_TEST_DATA;
const std::string kScenes = SCENE_CONFIG_DIR;

using aurorawall::test::loadError;

} // namespace

TEST(Scene, SubstormListsItsComponentsAndCurtains)
{
    const scene::Scene s = components::loadScene(kScenes + "/substorm.toml");
    EXPECT_TRUE(s.has("planet"));
    EXPECT_TRUE(s.has("aurora"));
    EXPECT_GE(s.settings<components::aurora::Settings>().curtains.size(), 3u);
    EXPECT_DOUBLE_EQ(s.planetRadiusKm, 6371.0);
}

// The scene's reach is its highest listed component's top: the substorm's aurora, without it the
// lower atmosphere's (the planet, the detail and the stars reach no higher than the ground); the
// glory's deck top, the plasma box's highest corner, the red airglow layer's top (40 upper scale
// heights above its base, where the shader's shell ends).
TEST(Scene, ReachIsTheHighestListedComponentsTop)
{
    scene::Scene s = components::loadScene(kScenes + "/substorm.toml");
    const double auroraTop = s.settings<components::aurora::Settings>().topKm;
    EXPECT_DOUBLE_EQ(s.reachRadiusKm(), s.planetRadiusKm + auroraTop);
    s.remove("fluid_detail");
    s.remove("aurora");
    EXPECT_DOUBLE_EQ(s.reachRadiusKm(), s.planetRadiusKm + 75.0); // the atmosphere's top_km
    s.remove("atmosphere");
    EXPECT_DOUBLE_EQ(s.reachRadiusKm(), s.planetRadiusKm);

    scene::Scene glory = components::loadScene(kScenes + "/glory-flight.toml");
    glory.remove("atmosphere");
    glory.remove("sky");
    EXPECT_DOUBLE_EQ(glory.reachRadiusKm(), glory.planetRadiusKm + 2.0); // deck_top_km

    scene::Scene box = components::loadScene(kScenes + "/plasma-box.toml");
    for (const char* other : {"aurora", "atmosphere", "airglow", "sky"})
        box.remove(other);
    EXPECT_DOUBLE_EQ(box.reachRadiusKm(), box.planetRadiusKm + 110.0 + 0.5 * std::sqrt(3.0) * 12.0); // box_altitude_km, box_side_km

    scene::Scene airglow = components::loadScene(kScenes + "/airglow-limb.toml");
    airglow.remove("atmosphere");
    double top = 0.0;
    for (const components::airglow::Layer& l : airglow.settings<components::airglow::Settings>().layers) {
        const components::airglow::LayerProfile p = components::airglow::layerProfile(l);
        top = std::max(top, p.baseKm + 40.0 * p.upperScaleHeightKm);
    }
    EXPECT_GT(top, 1000.0); // the red line's, far above its 250 km peak
    EXPECT_DOUBLE_EQ(airglow.reachRadiusKm(), airglow.planetRadiusKm + top);
}

TEST(Scene, BenchmarkCameraIsThePapersView)
{
    // The published benchmark camera: |C| = 1.011017 radii, about 70 km above southern Finland (59.2 N, 25.6 E),
    // heading 299 deg, 10.4 deg above the horizontal.
    const scene::Scene s = components::loadScene(kScenes + "/substorm.toml");
    const glm::dvec3 c = s.camera.positionKm;
    EXPECT_NEAR(glm::length(c) / 6371.0, 1.011017, 1e-6);
    EXPECT_NEAR(glm::length(c) - 6371.0, 70.0, 0.2);
    const double latitude = std::asin(c.z / glm::length(c)) * 180.0 / aurorawall::physics::kPi;
    EXPECT_NEAR(latitude, 59.2, 0.05);
    const glm::dvec3 zenith = glm::normalize(c);
    const double elevation = std::asin(glm::dot(s.camera.forward, zenith)) * 180.0 / aurorawall::physics::kPi;
    EXPECT_NEAR(elevation, 10.4, 0.1);
    EXPECT_NEAR(glm::dot(s.camera.forward, s.camera.up), 0.0, 1e-12);
}

TEST(Scene, WithoutUnmodelledDropsWhatTheReferenceDoesNotModel)
{
    // Every registered component listed: what is left is exactly what declares itself in the reference.
    scene::Scene all;
    for (const scene::Component* c : components::registry())
        all.add(*c);
    const scene::Scene modelled = scene::withoutUnmodelled(all);
    std::size_t dropped = 0;
    for (const scene::Component* c : components::registry()) {
        EXPECT_EQ(modelled.has(c->name()), c->inReference()) << c->name();
        dropped += c->inReference() ? 0 : 1;
    }
    EXPECT_GT(dropped, 0u);
    EXPECT_LT(dropped, components::registry().size());
}

TEST(Scene, GeographicCameraMatchesExplicitVectors)
{
    // The benchmark view written geographically lands on the same vectors as the explicit form.
    const glm::dvec3 p = scene::planetPoint(59.2, 25.6, 1.0);
    const glm::dvec3 reference = glm::normalize(glm::dvec3(-0.467287, -0.223999, 0.868115));
    EXPECT_NEAR(glm::dot(p, reference), 1.0, 1e-6);
}

TEST(Scene, ComponentsNotListedAreLeftOut)
{
    const scene::Scene s = components::loadScene(kData + "/minimal.toml");
    EXPECT_TRUE(s.has("stars"));
    EXPECT_FALSE(s.has("aurora"));
    EXPECT_FALSE(s.has("atmosphere"));
    EXPECT_NEAR(glm::length(s.camera.positionKm) - 6371.0, 0.001, 1e-9);
}

// Strings and comments with brackets and commas are read as written around a long one-line array.
TEST(Scene, LongOneLineArraysAndBracketsInStrings)
{
    const std::string good = kData + "/long_array_then_typo.toml";
    const std::string text = [&] {
        std::ifstream in(good);
        std::ostringstream s;
        s << in.rdbuf();
        return s.str();
    }();
    const std::string fixed = std::regex_replace(text, std::regex("energy_kev_typo"), "energy_kev");
    const std::string path = testing::TempDir() + "/long_array.toml";
    std::ofstream(path) << fixed;
    const scene::Scene s = components::loadScene(path);
    EXPECT_EQ(s.name, "arc [a, b], 'c' \"d, e\"");
    const auto& curtains = s.settings<components::aurora::Settings>().curtains;
    ASSERT_EQ(curtains.size(), 2u);
    EXPECT_EQ(curtains[0].keys.front().pointsLatLonDeg.size(), 60u);
    EXPECT_EQ(curtains[0].keys.front().pointsLatLonDeg[59], glm::dvec2(65.59, 19.5));
}

namespace {

// Curtains of `points` control points each on one line (the first array's line is 4), as a scene file.
std::string curtainScene(const std::string& name, std::size_t points, std::size_t curtains = 1)
{
    std::ostringstream text;
    text << "[scene]\ncomponents = [\"planet\", \"aurora\"]\n";
    for (std::size_t c = 0; c < curtains; ++c) {
        text << "[[aurora.curtain]]\npoints_lat_lon_deg = [";
        for (std::size_t k = 0; k < points; ++k)
            text << (k ? ", " : "") << "[" << 66.0 + 0.001 * double(k % 7) << ", " << -10.0 + 1e-3 * double(k) << "]";
        text << "]\n";
    }
    return aurorawall::test::temporarySceneFile(name, text.str());
}

} // namespace

// An inline array may have kMaxTomlArrayElements elements, a file kMaxTomlFileArrayElements in all
// (nested ones too); past either, one line names the array's line before toml11 parses the file.
TEST(SceneErrors, ArraysPastTheLimitsAreRefusedWithTheirLine)
{
    const std::size_t most = config::kMaxTomlArrayElements;
    EXPECT_EQ(loadError(curtainScene("at_limit.toml", most)).find("an array of"), std::string::npos);
    const std::string longer = curtainScene("past_limit.toml", most + 1);
    EXPECT_EQ(loadError(longer), longer + ":4: an array of more than 16384 elements, the most a config array may have");
    // Each curtain: its points and their two coordinates, 3 × 16000 elements; three fit, four do not.
    const std::string many = curtainScene("many_arrays.toml", 16000, 4);
    EXPECT_NE(loadError(many).find("array elements in the file, the most a config file may hold"), std::string::npos);
    EXPECT_EQ(loadError(curtainScene("fewer_arrays.toml", 16000, 2)).find("array elements"), std::string::npos);
}

// toml11 parses nested values recursively: nesting past kMaxTomlNesting is refused with its line
// before it can overflow the stack (10,000 levels did), in arrays and inline tables alike.
TEST(SceneErrors, NestingPastTheLimitIsRefusedWithItsLine)
{
    const auto nested = [](const char* name, std::size_t depth, char open, char close, const char* key) {
        std::string value;
        for (std::size_t i = 0; i < depth; ++i)
            value += std::string(1, open) + (open == '{' ? std::string(key) + " = " : "");
        value += "1" + std::string(depth, close);
        return aurorawall::test::temporarySceneFile(name, "[scene]\nname = \"n\"\ncomponents = [\"planet\"]\n"
                                                          "[planet]\nradius_km = " + value + "\n");
    };
    const std::size_t most = config::kMaxTomlNesting;
    for (std::size_t depth : {most + 1, std::size_t(100000)}) {
        const std::string arrays = nested("deep_arrays.toml", depth, '[', ']', "");
        EXPECT_EQ(loadError(arrays), arrays + ":5: arrays and inline tables nested more than 64 deep, the most a "
                                              "config file may have");
        const std::string tables = nested("deep_tables.toml", depth, '{', '}', "a");
        EXPECT_NE(loadError(tables).find(":5: arrays and inline tables nested more than 64"), std::string::npos);
    }
    // At the limit the file parses, and the value's type is what is wrong.
    EXPECT_NE(loadError(nested("at_nesting_limit.toml", most, '[', ']', "")).find("radius_km"), std::string::npos);
}

// toml11's time grows as the square of a dotted key's parts and of an inline table's entries: past
// kMaxTomlKeyParts and kMaxTomlInlineTableEntries the file is refused with the line, before parsing,
// in keys, table headers and inline tables alike; at the limits the file parses (and the unknown key
// is what is wrong).
TEST(SceneErrors, LongKeysAndInlineTablesAreRefusedWithTheirLine)
{
    const std::string head = "[scene]\nname = \"n\"\ncomponents = [\"planet\"]\n";
    const auto dotted = [](std::size_t parts) {
        std::string key = "a";
        for (std::size_t i = 1; i < parts; ++i)
            key += ".a";
        return key;
    };
    const auto inlineTable = [](std::size_t entries) {
        std::string table = "{";
        for (std::size_t i = 0; i < entries; ++i)
            table += (i ? ", k" : "k") + std::to_string(i) + " = 1.5";
        return table + "}";
    };
    const auto expectError = [&](const char* name, const std::string& body, const std::string& message) {
        const std::string error = aurorawall::test::loadErrorOfText(name, head + body);
        EXPECT_NE(error.find(message), std::string::npos) << name << ": " << error;
    };
    const std::size_t parts = config::kMaxTomlKeyParts, entries = config::kMaxTomlInlineTableEntries;
    for (std::size_t n : {parts + 1, std::size_t(40000)}) {
        expectError("long_key.toml", "[planet]\n" + dotted(n) + " = 1\n", ":5: a key of more than 16 dotted parts");
        expectError("long_header.toml", "[" + dotted(n) + "]\n", ":4: a key of more than 16 dotted parts");
        expectError("inline_key.toml", "[planet]\nx = {" + dotted(n) + " = 1}\n", ":5: a key of more than 16 dotted parts");
    }
    for (std::size_t n : {entries + 1, std::size_t(20000)})
        expectError("wide_table.toml", "[planet]\nx = " + inlineTable(n) + "\n", ":5: an inline table of more than 256 entries");
    expectError("key_at_limit.toml", "[planet]\n" + dotted(parts) + " = 1\n", "unknown");
    expectError("table_at_limit.toml", "[planet]\nx = " + inlineTable(entries) + "\n", "unknown");
}

// A camera needs a horizon: at (or within 1 km of) the planet's centre it has none, in any form.
TEST(SceneErrors, CameraAtThePlanetsCentreIsRefused)
{
    const std::string head = "[scene]\nname = \"c\"\ncomponents = [\"planet\"]\n[camera]\n";
    const std::string plain = head + "position_km = [0.0, 0.0, 0.0]\ndirection = [0.0, 0.0, 1.0]\nup = [0.0, 1.0, 0.0]\n";
    EXPECT_NE(aurorawall::test::loadErrorOfText("centre.toml", plain)
                  .find(":5: camera.position_km: must be at least 1 km from the planet's centre (got 0 km)"),
              std::string::npos);
    const std::string radii = head + "position_radii = [1e-5, 0.0, 0.0]\ndirection = [0.0, 0.0, 1.0]\nup = [0.0, 1.0, 0.0]\n";
    EXPECT_NE(aurorawall::test::loadErrorOfText("centre_radii.toml", radii).find("camera.position_radii: must be at least 1 km"),
              std::string::npos);
    std::string keys = head;
    for (int k = 0; k < 2; ++k)
        keys += "[[camera.key]]\ntime_s = " + std::to_string(k) + ".0\nposition_km = [0.0, 0.0, " + (k ? "0.5" : "7000.0") +
                "]\nheading_deg = 0.0\npitch_deg = 0.0\n";
    EXPECT_NE(aurorawall::test::loadErrorOfText("centre_key.toml", keys).find("position_km: must be at least 1 km"),
              std::string::npos);
    EXPECT_EQ(aurorawall::test::loadErrorOfText("one_km.toml", head + "position_km = [0.0, 1.0, 0.0]\ndirection = "
                                                                       "[0.0, 0.0, 1.0]\nup = [0.0, 1.0, 0.0]\n"),
              "");
}

// Direction and up are made orthonormal whatever their lengths; a zero vector, or an up along the view,
// is refused naming its key, in [camera] and in [[camera.key]] alike.
TEST(SceneErrors, CameraVectorsOfAnyLengthAreMadeOrthonormal)
{
    const auto camera = [](const std::string& direction, const std::string& up) {
        return "[scene]\nname = \"c\"\ncomponents = [\"planet\"]\n[camera]\nposition_km = [7000.0, 0.0, 0.0]\n"
               "direction = " + direction + "\nup = " + up + "\n";
    };
    const std::string tiny = aurorawall::test::temporarySceneFile("tiny.toml", camera("[0.0, 1e-300, 0.0]", "[0.0, 1e-300, 1e-10]"));
    const scene::Scene s = components::loadScene(tiny);
    EXPECT_EQ(s.camera.forward, glm::dvec3(0.0, 1.0, 0.0));
    EXPECT_EQ(s.camera.up, glm::dvec3(0.0, 0.0, 1.0));
    const scene::Scene huge = components::loadScene(
        aurorawall::test::temporarySceneFile("huge.toml", camera("[0.0, 1e12, 1e12]", "[0.0, 0.0, 1e12]")));
    EXPECT_NEAR(glm::length(huge.camera.forward), 1.0, 1e-15);
    EXPECT_NEAR(glm::dot(huge.camera.forward, huge.camera.up), 0.0, 1e-15);
    EXPECT_NE(aurorawall::test::loadErrorOfText("zero_up.toml", camera("[0.0, 1.0, 0.0]", "[0.0, 0.0, 0.0]"))
                  .find(":7: camera.up: must not be zero"),
              std::string::npos);
    EXPECT_NE(aurorawall::test::loadErrorOfText("zero_direction.toml", camera("[0.0, 0.0, 0.0]", "[0.0, 0.0, 1.0]"))
                  .find(":6: camera.direction: must not be zero"),
              std::string::npos);
    EXPECT_NE(aurorawall::test::loadErrorOfText("parallel.toml", camera("[0.0, 1.0, 0.0]", "[0.0, -1e-10, 1e-20]"))
                  .find("camera.up: must not be parallel to the view direction"),
              std::string::npos);
    const std::string keyed = "[scene]\nname = \"c\"\ncomponents = [\"planet\"]\n[camera]\n"
                              "[[camera.key]]\ntime_s = 0.0\nposition_km = [7000.0, 0.0, 0.0]\n"
                              "direction = [0.0, 1.0, 0.0]\nup = [0.0, 0.0, 1e-10]\n"
                              "[[camera.key]]\ntime_s = 1.0\nposition_km = [7000.0, 0.0, 0.0]\n"
                              "direction = [0.0, 1.0, 0.0]\nup = [0.0, 2.0, 0.0]\n";
    EXPECT_NE(aurorawall::test::loadErrorOfText("keyed.toml", keyed).find(":14: camera.key.up: must not be parallel"),
              std::string::npos)
        << aurorawall::test::loadErrorOfText("keyed.toml", keyed);
}

// Bytes that are not UTF-8 inside a string: the line and the problem, without toml11's function names.
TEST(SceneErrors, InvalidUtf8IsNamedWithItsLine)
{
    const std::string error =
        aurorawall::test::loadErrorOfText("utf8.toml", "[scene]\nname = \"\xff\"\ncomponents = [\"planet\"]\n");
    EXPECT_NE(error.find("utf8.toml:2: invalid utf8 sequence found"), std::string::npos) << error;
    EXPECT_EQ(error.find("parse_"), std::string::npos) << error;
}

TEST(SceneErrors, MissingFile)
{
    EXPECT_EQ(loadError(kData + "/nope.toml"), kData + "/nope.toml: scene file not found");
    EXPECT_EQ(loadError("/dev/zero"), "/dev/zero: not a regular file (a config file is a TOML text file)");
    // An empty file is read (and lacks its [scene]), not said to be unreadable.
    EXPECT_NE(aurorawall::test::loadErrorOfText("empty.toml", "").find("missing key 'scene'"), std::string::npos);
}

TEST(SceneErrors, NameFileAndLine)
{
    struct Case {
        const char* file;
        const char* where;   // file:line prefix expected
        const char* problem; // a part of the message
    };
    const Case cases[] = {
        {"syntax_error.toml", ":2: ", ""},
        {"unknown_key.toml", ":7: ", "unknown key 'planet.raduis_km'"},
        {"nan_value.toml", ":6: ", "atmosphere.scale_height_km: must be a finite number"},
        {"absurd_value.toml", ":8: ", "aurora.step_km: must be a finite number in [0.05, 100]"},
        {"absurd_resolve_cells.toml", ":9: ", "aurora.resolve_cells: must be a finite number in [0.05, 100]"},
        {"unknown_sub_step_flux.toml", ":9: ", "aurora.sub_step_flux"},
        {"unknown_component.toml", ":3: ", "unknown component 'rainbow'"},
        {"unlisted_table.toml", ":5: ", "unknown key 'stars'"},
        // Arrays are parsed with a line break after each comma: the lines are still the file's.
        {"long_array_then_typo.toml", ":19: ", "energy_kev_typo"},
        {"long_array_then_syntax_error.toml", ":7: ", ""},
    };
    for (const Case& c : cases) {
        const std::string file = kData + "/" + c.file;
        const std::string message = loadError(file);
        SCOPED_TRACE(message);
        EXPECT_EQ(message.rfind(file + c.where, 0), 0u) << c.file;
        EXPECT_NE(message.find(c.problem), std::string::npos) << c.file;
        EXPECT_EQ(message.find('\n'), std::string::npos) << "one line";
    }
}

// A count in a scene (cells, frames, steps, map texels, a seed) is a TOML integer: 64.5 is refused
// with its line, not truncated to 64.
TEST(SceneErrors, CountsMustBeIntegers)
{
    const std::string base = "[scene]\nbase = \"" + kScenes + "/twilight.toml\"\n";
    const std::pair<const char*, const char*> counts[] = {
        {"aurora", "footprint_map_size"}, {"aurora", "table_energy_count"}, {"sky", "view_steps"},
        {"sky", "light_steps"},           {"fluid_detail", "cells_along"},  {"fluid_detail", "cells_across"},
        {"fluid_detail", "frames"},       {"fluid_detail", "seed"}};
    for (const auto& [table, key] : counts) {
        const std::string error = aurorawall::test::loadErrorOfText(
            std::string("fraction_") + key + ".toml", base + "[" + table + "]\n" + key + " = 64.5\n");
        EXPECT_NE(error.find(std::string(":4: ") + table + "." + key + ": expected an integer"), std::string::npos)
            << error;
    }
    // The seed takes the whole 32-bit range.
    EXPECT_EQ(aurorawall::test::loadErrorOfText("seed_max.toml", base + "[fluid_detail]\nseed = 4294967295\n"), "");
    EXPECT_NE(aurorawall::test::loadErrorOfText("seed_over.toml", base + "[fluid_detail]\nseed = 4294967296\n")
                  .find("fluid_detail.seed: must be an integer in [0, 4294967295] (got 4294967296)"),
              std::string::npos);
}

// [scene] base names a scene file; one that is empty or names no file is refused at its own line.
TEST(SceneErrors, BaseMustNameASceneFile)
{
    for (const char* name : {"", "no-such-base.toml", "."}) {
        const std::string error = aurorawall::test::loadErrorOfText(
            "bad_base.toml", std::string("[scene]\nname = \"b\"\nbase = \"") + name + "\"\n");
        EXPECT_NE(error.find("bad_base.toml:3: scene.base: '" + std::string(name) + "' is not a scene file"),
                  std::string::npos)
            << error;
    }
}

// A required key that is missing, but given with a letter changed, added, left out or in another
// case, is named at the misspelt key's line.
TEST(SceneErrors, AMissingKeyPointsAtItsMisspelling)
{
    const std::string head = "[scene]\nname = \"m\"\ncomponents = [\"planet\"]\n[camera]\n";
    const std::string tail = "longitude_deg = 15.0\naltitude_km = 1.0\nheading_deg = 0.0\npitch_deg = 10.0\n";
    for (const char* typo : {"Latitude_deg", "latitude_dg", "latitudee_deg", "latitude_deb"}) {
        const std::string error =
            aurorawall::test::loadErrorOfText("typo.toml", head + tail + typo + " = 65.0\n");
        EXPECT_NE(error.find("typo.toml:9: missing key 'camera.latitude_deg' (misspelt as '" + std::string(typo) + "'?)"),
                  std::string::npos)
            << error;
    }
    // A key too different is not taken for the missing one.
    EXPECT_NE(aurorawall::test::loadErrorOfText("typo.toml", head + tail + "lat = 65.0\n")
                  .find("typo.toml:4: missing key 'camera.latitude_deg'"),
              std::string::npos);
}

// A camera entered on the ground is on the ground at every latitude: |planetPoint(R)| lands a few ulps of
// R either side of it, and altitudeKm takes that for 0; a millimetre above or below is kept.
TEST(Scene, PointsOnTheGroundHaveAltitudeZero)
{
    const double radius = 6371.0; // the planet of every shipped scene
    int below = 0;
    for (double lat = -90.0; lat <= 90.0; lat += 0.37)
        for (double lon : {-170.0, 0.0, 20.0, 133.3}) {
            const glm::dvec3 p = scene::planetPoint(lat, lon, radius);
            below += glm::length(p) < radius;
            EXPECT_EQ(scene::altitudeKm(p, radius), 0.0) << lat << ", " << lon;
            EXPECT_NEAR(scene::altitudeKm(scene::planetPoint(lat, lon, radius + 1e-6), radius), 1e-6, 1e-11);
            EXPECT_NEAR(scene::altitudeKm(scene::planetPoint(lat, lon, radius - 1e-6), radius), -1e-6, 1e-11);
        }
    EXPECT_GT(below, 0) << "no point fell below the sphere: the sweep does not test the rounding";
}

// An integer literal beyond 64 bits (which the TOML parser reads as the nearest limit) is named as such,
// not echoed as a number the file does not hold.
TEST(SceneErrors, IntegersBeyondSixtyFourBitsAreNamedSo)
{
    const std::string base = "[scene]\nbase = \"" + kScenes + "/quiet-arc.toml\"\n[aurora]\n";
    const std::string number =
        aurorawall::test::loadErrorOfText("huge_number.toml", base + "step_km = 99999999999999999999\n");
    EXPECT_NE(number.find(":4: aurora.step_km: must be a finite number in [0.05, 100] (got an integer beyond 64 bits)"),
              std::string::npos)
        << number;
    const std::string count =
        aurorawall::test::loadErrorOfText("huge_count.toml", base + "footprint_map_size = -99999999999999999999\n");
    EXPECT_NE(count.find(":4: aurora.footprint_map_size: must be an integer in [16, 8192] (got an integer beyond 64 bits)"),
              std::string::npos)
        << count;
}
