// The plasma box in the CPU reference (box_reference.h): the exact column on densities with a closed
// form (uniform: n times the chord; linear: its mean times the chord, the clamp along z included),
// the shader's march converging to it, the frame position in time, the march's knob, and the strip's
// frames the plasma gives the reference.
#include "physics/constants.h"
#include "components/plasma/box_reference.h"
#include "components/plasma/plasma.h"
#include "components/plasma/sheet_frames.h"
#include "components/registry.h"
#include "components/roles/curtain_detail.h"
#include "plasma_scene_text.h"
#include "scene/load_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

using namespace aurorawall;
using components::plasma::BoxDensity;
using components::plasma::BoxFrames;

namespace {

// Frames of `cells`³ whose value at cell centre u = ((i + ½)/n, (j + ½)/n, (k + ½)/n) of frame f is
// value(f, u).
template <class F>
BoxFrames framesOf(int cells, int frames, F value)
{
    BoxFrames b;
    b.cells = cells;
    b.frames = frames;
    for (int f = 0; f < frames; ++f)
        for (int k = 0; k < cells; ++k)
            for (int j = 0; j < cells; ++j)
                for (int i = 0; i < cells; ++i)
                    b.density.push_back(static_cast<float>(
                        value(f, glm::dvec3(i + 0.5, j + 0.5, k + 0.5) / double(cells))));
    return b;
}

struct Ray {
    glm::dvec3 o, d;
};

// A uniform frame (the values exact in float) and two frames mixed in time: n times the chord, to
// rounding (1e-12 relative).
TEST(PlasmaBoxReference, UniformDensityIsDensityTimesChord)
{
    const double side = 12.0, h = 6.0;
    const BoxFrames frames = framesOf(8, 3, [](int f, glm::dvec3) { return f == 0 ? 2.75 : f == 1 ? 0.5 : 4.0; });
    const double s3 = std::sqrt(3.0);
    const Ray rays[] = {
        {{-30.0, 1.0, -2.0}, {1.0, 0.0, 0.0}},
        {{-10.0, -10.0, -10.0}, glm::dvec3(1.0) / s3},
        {{0.3, -0.2, 0.1}, glm::normalize(glm::dvec3(0.0, 3.0, 4.0))},
        {{-20.0, 7.0, 3.0}, glm::normalize(glm::dvec3(2.0, -1.0, 0.3))},
    };
    struct Time {
        double position, n;
    };
    for (const Time time : {Time{0.0, 2.75}, Time{0.25, 0.75 * 2.75 + 0.25 * 0.5}, Time{2.0, 4.0}}) {
        const BoxDensity density(frames, time.position);
        for (const Ray& r : rays) {
            const glm::dvec2 segment = components::plasma::boxSegment(r.o, r.d, h);
            ASSERT_LT(segment.x, segment.y);
            const double chord = segment.y - segment.x;
            EXPECT_NEAR(density.exactColumn(r.o, r.d, segment, side), time.n * chord, 1e-12 * time.n * chord);
        }
    }
}

// n/n₀ = a + b x + c y + e z at the cell centres (x, y, z the unit coordinates): the lookup is that
// plane wherever no wrap across x or y is involved, and along z it is held at the first and last
// centres (δ = 1/(2n) from the faces). Rays with x and y within [δ, 1 − δ] over their chord: the
// column is (a + b x̄ + c ȳ)·chord + e·∫ clamp(z, δ, 1 − δ) dt, z linear in t from z₀ to z₁:
// chord·(G(z₁) − G(z₀))/(z₁ − z₀), G the clamp's antiderivative. To 1e-12 relative.
TEST(PlasmaBoxReference, LinearDensityMatchesTheClosedForm)
{
    const int cells = 16;
    const double side = 8.0, h = 4.0, a = 1.5, b = 0.25, c = -0.375, e = 0.75;
    const BoxFrames frames =
        framesOf(cells, 2, [&](int, glm::dvec3 u) { return a + b * u.x + c * u.y + e * u.z; });
    const BoxDensity density(frames, 0.5);
    const double delta = 0.5 / cells;
    const auto clampAntiderivative = [&](double z) {
        if (z <= delta)
            return delta * z;
        if (z <= 1.0 - delta)
            return delta * delta + 0.5 * (z * z - delta * delta);
        return delta * delta + 0.5 * ((1.0 - delta) * (1.0 - delta) - delta * delta) + (1.0 - delta) * (z - 1.0 + delta);
    };
    const Ray rays[] = {
        {{0.1, -0.2, -10.0}, glm::normalize(glm::dvec3(0.05, 0.08, 1.0))},  // bottom face to top face
        {{-0.5, 0.7, 10.0}, glm::normalize(glm::dvec3(0.1, -0.06, -1.0))},  // downwards
        {{0.2, 0.3, 0.9}, glm::normalize(glm::dvec3(-0.2, 0.1, 1.0))},      // from inside, upwards
        {{0.0, 0.0, -3.9}, glm::dvec3(0.0, 0.0, 1.0)},                       // inside the bottom half cell
    };
    for (const Ray& r : rays) {
        glm::dvec2 segment = components::plasma::boxSegment(r.o, r.d, h);
        segment.x = std::max(segment.x, 0.0);
        const glm::dvec3 u0 = (r.o + segment.x * r.d) / side + 0.5, u1 = (r.o + segment.y * r.d) / side + 0.5;
        for (const glm::dvec3& u : {u0, u1})
            ASSERT_TRUE(u.x >= delta && u.x <= 1.0 - delta && u.y >= delta && u.y <= 1.0 - delta);
        const double chord = segment.y - segment.x;
        const double along = (clampAntiderivative(u1.z) - clampAntiderivative(u0.z)) / (u1.z - u0.z);
        const double expected = (a + b * 0.5 * (u0.x + u1.x) + c * 0.5 * (u0.y + u1.y) + e * along) * chord;
        EXPECT_NEAR(density.exactColumn(r.o, r.d, segment, side), expected, 1e-12 * expected);
    }
}

// On a field with no closed form (products of sines across the wrap, two different frames mixed),
// the shader's midpoint march (the shared text, double) converges to the exact column at second
// order: with 2 steps per cell (the default) it is off by more than 1e-4 of the column, and 64
// times as many steps are at least 1000 times closer (4096 ideally).
TEST(PlasmaBoxReference, TheShadersMarchConvergesToTheExactColumn)
{
    const int cells = 16;
    const double side = 8.0, h = 4.0, pi = aurorawall::physics::kPi;
    const BoxFrames frames = framesOf(cells, 2, [&](int f, glm::dvec3 u) {
        return 1.0 + 0.6 * std::sin(2.0 * pi * (u.x + 0.3 * f)) * std::sin(4.0 * pi * u.y) * std::cos(6.0 * pi * u.z);
    });
    const BoxDensity density(frames, 0.4);
    const Ray r{{-9.0, -5.0, -7.0}, glm::normalize(glm::dvec3(1.0, 0.55, 0.8))};
    const glm::dvec2 segment = components::plasma::boxSegment(r.o, r.d, h);
    const double exact = density.exactColumn(r.o, r.d, segment, side);
    const double coarse = std::abs(density.marchedColumn(r.o, r.d, segment, 2 * cells, side) - exact);
    const double fine = std::abs(density.marchedColumn(r.o, r.d, segment, 128 * cells, side) - exact);
    std::printf("column %.6g: march of 2 steps per cell off by %.3g, 128 per cell by %.3g\n", exact, coarse, fine);
    EXPECT_GT(coarse, 1e-4 * exact);
    EXPECT_LT(fine, coarse / 1000.0);
}

// The frames play over box_play_s seconds, then again from frame 0.
TEST(PlasmaBoxReference, FramePositionLoopsOverThePlayTime)
{
    components::plasma::Settings p;
    p.boxFrames = 24;
    p.boxPlayS = 12.0;
    EXPECT_DOUBLE_EQ(components::plasma::boxFramePosition(p, 0.0), 0.0);
    EXPECT_DOUBLE_EQ(components::plasma::boxFramePosition(p, 6.0), 11.5);
    EXPECT_DOUBLE_EQ(components::plasma::boxFramePosition(p, 11.5), 23.0 * 11.5 / 12.0);
    EXPECT_DOUBLE_EQ(components::plasma::boxFramePosition(p, 12.0), 0.0);
    EXPECT_DOUBLE_EQ(components::plasma::boxFramePosition(p, 18.0), 11.5);
}

const std::string kHead = test::plasmaSceneHead() + "[plasma]\n";

// box_steps_per_cell: default 2, read with kind = "box", refused outside [1, 64] and with
// kind = "curls", the error naming file, line and key.
TEST(PlasmaBoxReference, StepsPerCellIsReadAndChecked)
{
    EXPECT_EQ(components::plasma::Settings().boxStepsPerCell, 2);
    const std::string file = testing::TempDir() + "plasma_box_steps.toml";
    std::ofstream(file) << kHead + "kind = \"box\"\nbox_cells = 16\nbox_steps_per_cell = 8\n";
    EXPECT_EQ(components::loadScene(file).settings<components::plasma::Settings>().boxStepsPerCell, 8);
    struct Case {
        std::string lines;
        int line; // of the key: the head has 12 lines
    };
    for (const Case& c : {Case{"kind = \"box\"\nbox_steps_per_cell = 0\n", 14},
                          Case{"kind = \"box\"\nbox_steps_per_cell = 65\n", 14},
                          Case{"box_steps_per_cell = 4\n", 13}}) {
        const std::string error = test::loadErrorOfText("plasma_box_steps.toml", kHead + c.lines);
        EXPECT_NE(error.find(file + ":" + std::to_string(c.line) + ": plasma.box_steps_per_cell"), std::string::npos)
            << c.lines << " -> " << error;
    }
}

// The frames the plasma gives the reference (the curtain detail role's referenceFrames) are the strip's simulation,
// bit for bit, with either kind.
TEST(PlasmaBoxReference, ReferenceFramesAreTheStripsFrames)
{
    const std::string strip = "cells_along = 128\ncells_across = 32\nstrip_width_km = 8.0\nsheet_thickness_km = 1.0\n"
                              "seed_mode = 4\nframes = 3\n";
    for (const std::string& kind : {std::string(), std::string("kind = \"box\"\nbox_cells = 16\nbox_seed_mode = 2\n")}) {
        const std::string file = testing::TempDir() + "plasma_reference_frames.toml";
        std::ofstream(file) << kHead + strip + kind;
        const scene::Scene scene = components::loadScene(file);
        const auto frames = components::roles::curtainDetailFrames(scene);
        ASSERT_TRUE(frames);
        const components::roles::FluxFrames expected = components::plasma::simulateSheetFrames(
            components::plasma::sheetFramesSpec(scene.settings<components::plasma::Settings>()));
        EXPECT_EQ(frames->nx, 128);
        EXPECT_EQ(frames->frames, 3);
        EXPECT_EQ(frames->flux, expected.flux);
    }
}

} // namespace
