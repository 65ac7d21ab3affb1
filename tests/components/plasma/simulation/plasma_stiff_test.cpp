// The plasma's stiff and extreme cases: ω_cΔt ≫ 1 with the Boris push (alone and self-consistent),
// ω_pΔt at the leapfrog's limit in a scene's settings.
#include "common/glsl.h"
#include "components/plasma/simulation/electrostatic_pic.h"
#include "components/plasma/simulation/particle_loading.h"
#include "components/plasma/simulation/particle_mesh.h"
#include "components/plasma/simulation/plasma_parameters.h"
#include "scene/load_error.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

// The push in double (a named namespace: not every function is used).
namespace aurorawall::plasma_stiff_test::f64 {
AURORAWALL_GLSL_PRECISION(double)
#include "components/plasma/boris_push.glsl"
} // namespace aurorawall::plasma_stiff_test::f64

using namespace aurorawall;
using namespace aurorawall::components::plasma::simulation;
namespace boris = aurorawall::plasma_stiff_test::f64;

namespace {

constexpr double kChargeOverMass = -kElementaryCharge / kElectronMass;

// The centre of the circle through three points.
glm::dvec3 circumcentre(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c)
{
    const glm::dvec3 u = b - a, w = c - a, n = glm::cross(u, w);
    return a + glm::cross(glm::dot(u, u) * w - glm::dot(w, w) * u, n) / (2.0 * glm::dot(n, n));
}

const std::string kSceneHead = "[scene]\nname = \"t\"\ncomponents = [\"planet\", \"aurora\", \"plasma\"]\n"
                               "[camera]\nlatitude_deg = 0.0\nlongitude_deg = 0.0\naltitude_km = 1.0\n"
                               "heading_deg = 0.0\nelevation_deg = 10.0\n"
                               "[[aurora.curtain]]\npoints_lat_lon_deg = [[0.0, 0.0], [0.0, 1.0]]\n";

} // namespace

// Pure B, ω_cΔt = 10, 100, 1000: the Boris orbit of every electron is a polygon inscribed in a circle of
// radius |v⊥|Δt/(2 sin(θ/2)), θ = 2 atan(ω_cΔt/2) (the gyration stays bounded, on a radius inflated
// from v⊥/ω_c to about v⊥Δt/2), the motion along B is exact and |v| (the energy) changes only by
// rounding. Measured over 1e4 steps, 16 electrons each: radius within 8.3e-12, 1.0e-11, 1.3e-11,
// |v| within 1.1e-12, 1.7e-12, 5.6e-13, the motion along B within 2.8e-13 (relative).
TEST(PlasmaStiff, BorisGyrationStaysOnItsCircleAtLargeOmegaCDt)
{
    const glm::dvec3 b(0.0, 0.0, 5e-5), unit(0.0, 0.0, 1.0);
    std::mt19937_64 random(7);
    std::normal_distribution<double> normal(0.0, 4.19e5); // m/s: 1 eV electrons
    for (const double wcDt : {10.0, 100.0, 1000.0}) {
        const double dt = wcDt / cyclotronFrequency(glm::length(b)), theta = 2.0 * std::atan(0.5 * wcDt);
        double worstRadius = 0.0, worstSpeed = 0.0, worstParallel = 0.0;
        for (int particle = 0; particle < 16; ++particle) {
            glm::dvec3 v(normal(random), normal(random), std::abs(normal(random))); // along +B: no wrap from z = 0
            const double speed = glm::length(v), along = glm::dot(v, unit);
            const double radius = glm::length(v - along * unit) * dt / (2.0 * std::sin(0.5 * theta));
            // No wrap: across B the box is 1000 orbit radii (positions round to about 1e-13 of the radius),
            // along B 1e7 m.
            const glm::dvec3 box(1000.0 * radius, 1000.0 * radius, 1e7), start(0.5 * box.x, 0.5 * box.y, 0.0);
            std::vector<glm::dvec3> x = {start};
            for (int n = 0; n < 10000; ++n) {
                v = boris::borisVelocity(v, glm::dvec3(0.0), b, kChargeOverMass, dt);
                x.push_back(boris::leapfrogPosition(x.back(), v, dt, box));
                worstSpeed = std::max(worstSpeed, std::abs(glm::length(v) - speed) / speed);
            }
            // Across B: every point at the same distance from the circle's centre (the guiding centre).
            const auto across = [&](glm::dvec3 p) { return p - glm::dot(p - start, unit) * unit; };
            const glm::dvec3 centre = circumcentre(across(x[1]), across(x[2]), across(x[3]));
            for (std::size_t n = 1; n < x.size(); ++n) {
                worstRadius = std::max(worstRadius, std::abs(glm::length(across(x[n]) - centre) - radius) / radius);
                worstParallel = std::max(worstParallel, std::abs(glm::dot(x[n] - start, unit) - double(n) * along * dt) /
                                                            (double(n) * std::abs(along) * dt));
            }
        }
        EXPECT_LT(worstRadius, 1e-10) << "omega_c dt = " << wcDt;
        EXPECT_LT(worstSpeed, 1e-11) << "omega_c dt = " << wcDt; // 1e-15 a step, as PlasmaVerify's Boris test
        EXPECT_LT(worstParallel, 1e-12) << "omega_c dt = " << wcDt;
    }
}

// A self-consistent thermal plasma (1 eV, random start, seed 3, Δx = λ_D, 16 cells × 32 per cell,
// ω_pΔt = 0.2) across B (x resolved, B along z) at ω_cΔt = 10, 100, 1000 (ω_c/ω_p = 50, 500, 5000):
// over 1e4 steps (2000/ω_p) the total energy stays within 5% of its start, and at 100 and 1000, where
// the electrons barely move across B, closer than without B. Measured largest relative energy
// change: 3.5e-2, 9.0e-4, 4.7e-4; without B 9.4e-3 (docs/PLASMA.md, "Stiff and extreme cases").
TEST(PlasmaStiff, SelfConsistentEnergyKeptAtLargeOmegaCDt)
{
    const double density = 1e12, thermalSpeed = 4.19e5, wp = plasmaFrequency(density), dt = 0.2 / wp;
    const PeriodicGrid grid(1, {16, 1, 1}, {debyeLength(thermalSpeed, density), 1.0, 1.0});
    const auto largestEnergyChange = [&](double wcDt) {
        const double b = wcDt / dt * kElectronMass / kElementaryCharge;
        ElectrostaticPic pic(grid, randomStart(grid, 16 * 32, density, thermalSpeed, 3), glm::dvec3(0.0, 0.0, b), dt);
        const double initial = pic.step().total();
        double worst = 0.0;
        for (int n = 1; n < 10000; ++n)
            worst = std::max(worst, std::abs(pic.step().total() - initial) / initial);
        return worst;
    };
    const double unmagnetised = largestEnergyChange(0.0);
    for (const double wcDt : {10.0, 100.0, 1000.0}) {
        const double worst = largestEnergyChange(wcDt);
        EXPECT_LT(worst, 0.05) << "omega_c dt = " << wcDt;
        if (wcDt >= 100.0) {
            EXPECT_LT(worst, unmagnetised) << "omega_c dt = " << wcDt;
        }
    }
}

// ω_pΔt just below 2 is accepted and just above refused, naming the key, for the strip and the box
// (ω_p = 1.784e5 rad/s at the default 1e7 m⁻³: Δt = 1.115e-5 s is 1.99, 1.127e-5 s is 2.01); the box
// also refuses a step its beams cross a cell in.
TEST(PlasmaStiff, ScenesRefuseOmegaPDtFromTwo)
{
    const auto error = [](const std::string& plasma) { return test::loadErrorOfText("stiff.toml", kSceneHead + plasma); };
    const double wp = plasmaFrequency(1e7);
    const auto dt = [wp](double wpDt) {
        char text[32];
        std::snprintf(text, sizeof text, "%.10g", wpDt / wp);
        return std::string(text);
    };
    EXPECT_EQ(error("[plasma]\ntime_step_s = " + dt(1.99) + "\ntime_between_frames_s = 1e-4\n"), "");
    const std::string strip = error("[plasma]\ntime_step_s = " + dt(2.01) + "\ntime_between_frames_s = 1e-4\n");
    EXPECT_NE(strip.find("plasma.time_step_s: omega_p dt = 2.01 must be below 2"), std::string::npos) << strip;
    // The box's beams must also cross less than a cell a step: at 1.99 the default seed mode's beams
    // cross about 1.5, the shortest mode's (half the speed) fewer than 1.
    EXPECT_EQ(error("[plasma]\nkind = \"box\"\nbox_seed_mode = 8\nbox_time_step_s = " + dt(1.99) +
                    "\nbox_time_between_frames_s = 1e-4\n"),
              "");
    const std::string courant =
        error("[plasma]\nkind = \"box\"\nbox_time_step_s = " + dt(1.99) + "\nbox_time_between_frames_s = 1e-4\n");
    EXPECT_NE(courant.find("plasma.box_time_step_s: the beams cross 1."), std::string::npos) << courant;
    EXPECT_NE(courant.find(" cells a step; at most 1 (lower box_time_step_s)"), std::string::npos) << courant;
    const std::string box =
        error("[plasma]\nkind = \"box\"\nbox_time_step_s = " + dt(2.01) + "\nbox_time_between_frames_s = 1e-4\n");
    EXPECT_NE(box.find("plasma.box_time_step_s: omega_p dt = 2.01 must be below 2"), std::string::npos) << box;
}
