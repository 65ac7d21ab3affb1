// The glory's optics (src/components/glory/optics) against independent references, and the physics
// of its rings: where the first red ring lies, what a spread of drop sizes and the Sun's disc do.
#include "physics/constants.h"
#include "components/glory/glory.h"
#include "components/glory/mie/mie_coefficients.h"
#include "components/glory/mie/mie_scattering.h"
#include "components/glory/mie/phase_function.h"
#include "physics/colour_matching.h"
#include "physics/spectra.h"
#include "components/glory/optics/glory_table.h"
#include "components/glory/optics/light_source.h"
#include "components/glory/optics/water.h"
#include "components/registry.h"
#include "scene/load_error.h"
#include "scene/ray_steps.h"
#include "scene/scene.h"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace aurorawall;
using namespace aurorawall::components::glory::optics;
namespace aurorawall::components::glory::deck {
using namespace aurorawall::scene::f64;
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include "physics/constants.glsl"
#include "components/glory/cloud_deck.glsl"
#pragma GCC diagnostic pop
} // namespace aurorawall::components::glory::deck

namespace mie = aurorawall::components::glory::mie;

namespace {


// A table of the glory's region only (0–10° every 0.05°), with `wavelengths` from 400 to 700 nm.
GloryTableSpec ringSpec(int wavelengths)
{
    GloryTableSpec spec;
    spec.angles.glorySpanRad = 10.0 * aurorawall::physics::kDegree;
    spec.angles.gloryCount = 201;
    spec.angles.middleCount = 16;
    spec.angles.forwardCount = 16;
    spec.wavelengthCount = wavelengths;
    spec.firstNm = 400.0;
    spec.lastNm = 700.0;
    spec.sizeParameterStep = 0.2;
    return spec;
}

struct Rings {
    std::vector<double> luminanceMaximaDeg; // local maxima of Y(γ), 0.3° < γ < 10°
    double firstRedRingDeg = -1.0;          // the first maximum of r = R/(R+G+B) beyond the first maximum of Y
    double firstRingContrast = 0.0;         // (Y_max − Y_min)/(Y_max + Y_min) of the first ring and the minimum inside it
};

Rings rings(const PhaseTable& table, const LightSource& light)
{
    const std::vector<glm::dvec3> xyz = gloryXyz(table, light);
    const std::vector<glm::dvec3> rgb = gloryLinearSrgb(xyz);
    Rings r;
    const int last = table.angles.gloryCount - 2;
    double previousMinimum = xyz[0].y;
    for (int i = 1; i <= last; ++i) {
        const double gamma = table.angles.angle(i) / aurorawall::physics::kDegree;
        if (xyz[i].y < xyz[i - 1].y && xyz[i].y <= xyz[i + 1].y && r.luminanceMaximaDeg.empty())
            previousMinimum = xyz[i].y;
        if (gamma > 0.3 && xyz[i].y > xyz[i - 1].y && xyz[i].y >= xyz[i + 1].y) {
            if (r.luminanceMaximaDeg.empty())
                r.firstRingContrast = (xyz[i].y - previousMinimum) / (xyz[i].y + previousMinimum);
            r.luminanceMaximaDeg.push_back(gamma);
        }
    }
    auto redness = [&](int i) { return rgb[i].r / (rgb[i].r + rgb[i].g + rgb[i].b); };
    if (!r.luminanceMaximaDeg.empty())
        for (int i = 1; i <= last; ++i) {
            const double gamma = table.angles.angle(i) / aurorawall::physics::kDegree;
            if (gamma > r.luminanceMaximaDeg.front() && redness(i) > redness(i - 1) && redness(i) >= redness(i + 1)) {
                r.firstRedRingDeg = gamma;
                break;
            }
        }
    return r;
}

Rings ringsOf(double radiusUm, double variance, double discDiameterDeg)
{
    const mie::DropSizeDistribution drops =
        variance > 0.0 ? mie::DropSizeDistribution::gamma(radiusUm, variance) : mie::DropSizeDistribution::singleSize(radiusUm);
    LightSource sun;
    sun.angularDiameterDeg = discDiameterDeg;
    GloryTableSpec spec = ringSpec(8);
    spec.sizeParameterStep = 0.3;
    return rings(smearedByDisc(phaseTable(drops, spec), sun.discRadiusRad()), sun);
}

} // namespace

TEST(ColourMatching, TableValuesAndInterpolation)
{
    EXPECT_DOUBLE_EQ(physics::colourMatching(555.0).y, 1.0);
    EXPECT_DOUBLE_EQ(physics::colourMatching(380.0).z, 0.006450);
    EXPECT_DOUBLE_EQ(physics::colourMatching(600.0).x, 1.0622);
    EXPECT_NEAR(physics::colourMatching(602.5).x, 0.5 * (1.0622 + 1.0456), 1e-12);
    EXPECT_EQ(physics::colourMatching(379.0), glm::dvec3(0.0));
    EXPECT_EQ(physics::colourMatching(781.0), glm::dvec3(0.0));
    EXPECT_EQ(physics::colourMatching(std::nan("")), glm::dvec3(0.0));
}

// Daimon & Masumura's fit against the handbook value of water at 20 °C at the sodium D line
// (n_D = 1.3330) and their own tabulated trend: normal dispersion across the visible.
TEST(Water, RefractiveIndex)
{
    EXPECT_NEAR(waterRefractiveIndex(589.3), 1.3330, 5e-4);
    double previous = 10.0;
    for (double nm = 380.0; nm <= 780.0; nm += 20.0) {
        EXPECT_LT(waterRefractiveIndex(nm), previous) << nm;
        previous = waterRefractiveIndex(nm);
    }
    EXPECT_NEAR(waterRefractiveIndex(400.0) - waterRefractiveIndex(700.0), 0.0130, 1e-3);
}

// The light's spectrum reproduces its illuminance under an independent quadrature (adaptive
// Gauss–Kronrod over the table's pieces); Planck's peak is Wien's; the full Moon's illuminance is
// the closed form of a Lambert sphere.
TEST(LightSource, IlluminanceSpectrumAndMoon)
{
    LightSource sun;
    double lux = 0.0;
    for (double nm = physics::kCieFirstNm; nm < physics::kCieLastNm; nm += physics::kCieStepNm)
        lux += boost::math::quadrature::gauss_kronrod<double, 15>::integrate(
            [&](double l) { return physics::kLumensPerWatt * sun.spectralIrradiance(l) * physics::colourMatching(l).y; }, nm, nm + physics::kCieStepNm);
    EXPECT_NEAR(lux / sun.sunIlluminanceLux, 1.0, 2e-4);

    double peakNm = 0.0, peak = 0.0;
    for (double nm = 300.0; nm <= 800.0; nm += 0.1)
        if (physics::planckRadiance(nm, 5778.0) > peak) {
            peak = physics::planckRadiance(nm, 5778.0);
            peakNm = nm;
        }
    EXPECT_NEAR(peakNm, 2.897771955e6 / 5778.0, 0.1); // Wien: λ_max T = 2.897771955e-3 m K

    LightSource moon;
    moon.body = LightSource::Body::Moon;
    const double full = 1.28e5 * 0.12 * std::pow(1737.4 / 384400.0, 2);
    EXPECT_NEAR(moon.illuminanceLux(), full, 1e-12 * full);
    moon.moonPhaseAngleDeg = 90.0;
    EXPECT_NEAR(moon.illuminanceLux(), full / aurorawall::physics::kPi, 1e-12 * full);
    EXPECT_NEAR(moon.spectralIrradiance(550.0) / sun.spectralIrradiance(550.0), full / aurorawall::physics::kPi / 1.28e5, 1e-12);
}

// One drop: the table equals the phase function from the Mie amplitudes summed independently at
// the same angles, 4 S11 / (x² Qsca), and integrates to 1 over the sphere.
TEST(GloryTable, SingleDropIsTheMiePhaseFunction)
{
    GloryTableSpec spec = ringSpec(2);
    spec.angles.glorySpanRad = 30.0 * aurorawall::physics::kDegree;
    spec.angles.middleCount = 3000;
    spec.angles.forwardCount = 600;
    const PhaseTable table = phaseTable(mie::DropSizeDistribution::singleSize(3.0), spec);
    for (int w = 0; w < 2; ++w) {
        const double nm = table.wavelengthsNm[size_t(w)];
        const double x = 2.0 * aurorawall::physics::kPi * 3.0 / (nm * 1e-3);
        const mie::MieCoefficients c = mie::mieCoefficients(x, {waterRefractiveIndex(nm), 0.0});
        const double qsca = mie::efficiencies(c).scattering;
        for (int a : {0, 1, 200, 400, 1000, spec.angles.size() - 1}) {
            const mie::Amplitudes s = mie::amplitudesAtCosine(c, -std::cos(table.angles.angle(a)));
            const double expected = 2.0 * (std::norm(s.s1) + std::norm(s.s2)) / (x * x * qsca);
            EXPECT_NEAR(table.at(w, a) / expected, 1.0, 1e-12) << nm << " nm, angle " << a;
        }
        double integral = 0.0; // ∫ P dΩ/4π = ½ ∫ P sin γ dγ, trapezoid over the grid
        for (int a = 0; a + 1 < spec.angles.size(); ++a) {
            const double g0 = table.angles.angle(a), g1 = table.angles.angle(a + 1);
            integral += 0.25 * (g1 - g0) * (table.at(w, a) * std::sin(g0) + table.at(w, a + 1) * std::sin(g1));
        }
        EXPECT_NEAR(integral, 1.0, 2e-3) << nm; // the trapezoid's error on the forward peak
    }
}

// The radius quadrature against the adaptive Gauss–Kronrod average of the Mie library (tolerance
// 1e-6), which resolves the narrow Mie resonances that the even nodes sample: measured largest
// relative differences 5.7e-2 at step 0.2 and 2.3e-3 at 0.05 (docs/GLORY.md, "Error against run time").
TEST(GloryTable, SizeAverageAgreesWithTheAdaptiveQuadrature)
{
    const mie::DropSizeDistribution drops = mie::DropSizeDistribution::gamma(4.0, 0.02);
    const std::vector<int> indices = {0, 20, 60, 200, 210};
    for (double step : {0.2, 0.05}) {
        GloryTableSpec spec = ringSpec(1);
        spec.firstNm = spec.lastNm = 550.0;
        spec.sizeParameterStep = step;
        const PhaseTable table = phaseTable(drops, spec);
        std::vector<double> angles;
        for (int i : indices)
            angles.push_back(aurorawall::physics::kPi - table.angles.angle(i));
        const mie::PhaseFunction exact = mie::sizeAveragedPhaseFunction(drops, 0.55, {waterRefractiveIndex(550.0), 0.0}, angles);
        double worst = 0.0;
        for (size_t k = 0; k < indices.size(); ++k)
            worst = std::max(worst, std::abs(table.at(0, indices[k]) / exact.value[k] - 1.0));
        std::printf("size parameter step %.2f: largest relative difference %.2g\n", step, worst);
        EXPECT_LT(worst, step > 0.1 ? 0.08 : 4e-3);
    }
}

// The disc average of P(γ) = γ² (flat-sky limit): γ² + ρ²/2 exactly, and a constant stays constant.
TEST(GloryTable, DiscSmearingAveragesOverTheDisc)
{
    GloryTableSpec spec = ringSpec(2);
    PhaseTable table = emptyPhaseTable(spec);
    for (int w = 0; w < 2; ++w)
        for (int a = 0; a < spec.angles.size(); ++a)
            table.values[size_t(w) * size_t(spec.angles.size()) + size_t(a)] =
                w == 0 ? 1.0 : std::pow(table.angles.angle(a), 2);
    const double rho = 0.25 * aurorawall::physics::kDegree;
    const PhaseTable smeared = smearedByDisc(table, rho);
    for (int a : {0, 20, 100, 180}) { // at least ρ inside the span, where the grid is even
        const double gamma = table.angles.angle(a);
        EXPECT_NEAR(smeared.at(0, a), 1.0, 1e-14);
        // Linear interpolation of γ² between samples h apart adds at most h²/4.
        const double h = spec.angles.glorySpanRad / (spec.angles.gloryCount - 1);
        EXPECT_NEAR(smeared.at(1, a), gamma * gamma + 0.5 * rho * rho, 0.25 * h * h + 1e-3 * rho * rho) << a;
    }
}

// The first red ring (the reddest angle beyond the first bright ring), with the Sun's disc: about 4°
// for 5 µm drops and about 1.3° for 20 µm (Laven 2005, "How are glories formed?", Appl. Opt. 44,
// 5675). Measured 4.3° and 1.1° (1.10° with 41 wavelengths every 0.025°); held within 20%.
TEST(GloryRings, FirstRedRingPosition)
{
    const Rings small = ringsOf(5.0, 0.0025, 0.533), large = ringsOf(20.0, 0.0025, 0.533);
    std::printf("first red ring: 5 um %.2f deg, 20 um %.2f deg\n", small.firstRedRingDeg, large.firstRedRingDeg);
    EXPECT_NEAR(small.firstRedRingDeg, 4.0, 0.8);
    EXPECT_NEAR(large.firstRedRingDeg, 1.3, 0.26);
}

// A 20% spread of sizes (effective variance 0.04) leaves only the inner ring within 10°; one size
// shows several.
TEST(GloryRings, TwentyPercentSpreadLeavesOnlyTheInnerRing)
{
    EXPECT_GE(ringsOf(5.0, 0.0, 0.533).luminanceMaximaDeg.size(), 3u);
    EXPECT_EQ(ringsOf(5.0, 0.04, 0.533).luminanceMaximaDeg.size(), 1u);
}

// The fine structure: for one size the successive rings' brightness jumps up and down (the glory's
// rings beat with a finer ripple); a 5% spread (variance 0.0025) leaves rings that fade steadily.
TEST(GloryRings, FivePercentSpreadRemovesTheFineStructure)
{
    auto steadilyFading = [](double radius, double variance) {
        const mie::DropSizeDistribution drops = variance > 0.0 ? mie::DropSizeDistribution::gamma(radius, variance)
                                                               : mie::DropSizeDistribution::singleSize(radius);
        GloryTableSpec spec = ringSpec(1);
        spec.firstNm = spec.lastNm = 550.0;
        const PhaseTable table = phaseTable(drops, spec);
        std::vector<double> peaks;
        for (int i = 1; i + 1 < spec.angles.gloryCount && table.angles.angle(i) < 5.0 * aurorawall::physics::kDegree; ++i)
            if (table.at(0, i) > table.at(0, i - 1) && table.at(0, i) >= table.at(0, i + 1))
                peaks.push_back(table.at(0, i));
        for (size_t k = 1; k < peaks.size(); ++k)
            if (peaks[k] > peaks[k - 1])
                return false;
        return peaks.size() >= 3;
    };
    EXPECT_FALSE(steadilyFading(20.0, 0.0));
    EXPECT_TRUE(steadilyFading(20.0, 0.0025));
}

// Drops above about 25 µm: the Sun's 0.53° disc smears the rings away. The first ring's contrast
// (measured 9% at 20 µm, 2% at 25 µm, 1.7% at 30 µm with the disc; 24% at 30 µm without it).
TEST(GloryRings, TheSunsDiscHidesTheGloryOfLargeDrops)
{
    const Rings withDisc = ringsOf(30.0, 0.0025, 0.533), pointSun = ringsOf(30.0, 0.0025, 0.0);
    std::printf("30 um first ring contrast: %.3f with the disc, %.3f without\n", withDisc.firstRingContrast,
                pointSun.firstRingContrast);
    EXPECT_LT(withDisc.firstRingContrast, 0.03);
    EXPECT_GT(pointSun.firstRingContrast, 0.15);
    EXPECT_GT(ringsOf(20.0, 0.0025, 0.533).firstRingContrast, 0.06);
}

namespace {

const std::string kDeck = "[scene]\nname = \"deck\"\ncomponents = [\"planet\", \"atmosphere\", \"glory\"]\n"
                          "[camera]\nlatitude_deg = 60.0\nlongitude_deg = 10.0\naltitude_km = 3.0\n"
                          "heading_deg = 0.0\nelevation_deg = -10.0\n";
const std::string kLight = "[glory.light]\nsite_latitude_deg = 60.0\nsite_longitude_deg = 10.0\n"
                           "elevation_deg = 20.0\nazimuth_deg = 180.0\n";

} // namespace

// A scene derived from one with a glory changes its drops and keeps its light.
TEST(GlorySettings, DerivedSceneKeepsItsBasesLight)
{
    const std::string base = std::string(AURORAWALL_SOURCE_DIR) + "/config/scenes/glory-flight.toml";
    const std::string derived =
        test::temporarySceneFile("derived-glory.toml", "[scene]\nbase = \"" + base + "\"\n[glory]\neffective_radius_um = 5.0\n");
    const scene::Scene a = components::loadScene(base), b = components::loadScene(derived);
    const auto& sa = a.settings<components::glory::Settings>();
    const auto& sb = b.settings<components::glory::Settings>();
    EXPECT_EQ(sb.effectiveRadiusUm, 5.0);
    EXPECT_EQ(sb.lightDirection, sa.lightDirection);
    EXPECT_GT(glm::length(sa.lightDirection - glm::dvec3(0.0, 0.0, 1.0)), 0.1);
}

// Bad glory tables: one error naming the file, the line and the key.
TEST(GlorySettings, BadInputNamesFileLineAndKey)
{
    struct Case {
        std::string name, text, expected;
    };
    const std::vector<Case> cases = {
        {"no-light.toml", kDeck + "[glory]\ndeck_top_km = 1.0\n", "no-light.toml:10: glory.light: missing"},
        {"deck-in-ground.toml", kDeck + "[glory]\ndeck_top_km = 1.0\ndeck_thickness_km = 2.0\n" + kLight,
         "deck-in-ground.toml:12: glory.deck_thickness_km: the deck's base"},
        {"deck-in-space.toml", kDeck + "[glory]\ndeck_top_km = 80.0\n" + kLight, "glory.deck_top_km: must be"},
        {"nan-radius.toml", kDeck + "[glory]\neffective_radius_um = nan\n" + kLight,
         "nan-radius.toml:11: glory.effective_radius_um: must be a finite number"},
        {"moon-key-on-sun.toml", kDeck + "[glory]\n" + kLight + "albedo = 0.1\n", "unknown key 'glory.light.albedo'"},
        {"bad-sampling.toml", kDeck + "[glory]\nwavelength_sampling = \"random\"\n" + kLight,
         "bad-sampling.toml:11: glory.wavelength_sampling: must be one of"},
        {"hours-of-table.toml", kDeck + "[glory]\neffective_radius_um = 50.0\neffective_variance = 0.3\n" + kLight,
         "hours-of-table.toml:12: glory.effective_variance: the glory table would sum 6.6e+12 Mie terms times angles"},
    };
    for (const Case& c : cases) {
        const std::string message = test::loadErrorOfText(c.name, c.text);
        EXPECT_NE(message.find(c.expected), std::string::npos) << c.name << ": " << message;
    }
}

// The table's work (phaseTableWork) counts what phaseTable does: a single size is one series a
// wavelength, wiscombeTermCount(x) terms long, each reaching every angle. The default drops' table is
// far within the budget a scene may ask for, and single sizes up to the largest radius too.
TEST(GlorySettings, TableWorkCountsTheSeriesTermsAndAngles)
{
    GloryTableSpec spec;
    spec.wavelengthCount = 2;
    double terms = 0.0;
    for (const double nm : {spec.firstNm, spec.lastNm})
        terms += mie::wiscombeTermCount(2.0 * physics::kPi * 20.0 / (nm * 1e-3));
    EXPECT_EQ(phaseTableWork(mie::DropSizeDistribution::singleSize(20.0), spec), terms * spec.angles.size());
    const std::string single = kDeck + "[glory]\neffective_radius_um = 50.0\neffective_variance = 0.0\n" + kLight;
    EXPECT_EQ(test::loadErrorOfText("one-size.toml", single), "");
    EXPECT_EQ(test::loadErrorOfText("default-drops.toml", kDeck + "[glory]\n" + kLight), "");
}

// A camera on the deck's top (or base) is outside it: looking away it sees no deck, looking into it
// meets the deck at once; inside, the deck is at 0 in every direction (km; the deck 1 to 2 km up).
TEST(CloudDeck, ACameraOnItsSurfaceIsOutside)
{
    using components::glory::deck::cloudDeckHit;
    const double R = 6371.0, base = 1.0, top = 2.0;
    const glm::dvec3 up(0.0, 0.0, 1.0), along(1.0, 0.0, 0.0);
    for (double altitude : {top, base}) {
        const glm::dvec3 o = (R + altitude) * up;
        const double away = cloudDeckHit(o, altitude == top ? up : -up, R, altitude, base, top);
        const double into = cloudDeckHit(o, altitude == top ? -up : up, R, altitude, base, top);
        EXPECT_TRUE(away < 0.0 || away > 2.0 * R) << "camera at " << altitude << " km, looking away: " << away;
        EXPECT_EQ(into, 0.0) << "camera at " << altitude << " km, looking into the deck";
    }
    const glm::dvec3 inside = (R + 1.5) * up;
    for (const glm::dvec3& d : {up, -up, along})
        EXPECT_EQ(cloudDeckHit(inside, d, R, 1.5, base, top), 0.0);
    // Above the top, looking down: the top at the height difference.
    EXPECT_NEAR(cloudDeckHit((R + 5.0) * up, -up, R, 5.0, base, top), 3.0, 1e-9);
}
