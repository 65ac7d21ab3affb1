// Tests of the airmass methods (issue 4): exact reference, published error figures, extreme cases, CLI.
#include "atmosphere/airmass.h"
#include "atmosphere/airmass_accuracy.h"
#include "atmosphere/airmass_cli.h"
#include "atmosphere/airmass_exact.h"
#include "common/glsl.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

// The shared erf helpers in double, to test them directly.
namespace aurorawall::test64 {
AURORAWALL_GLSL_PRECISION(double)
#include "atmosphere/airmass_common.glsl"
} // namespace aurorawall::test64

namespace aurorawall {
namespace {

constexpr double kR = 6371.0;
double radians(double degrees) { return degrees * M_PI / 180.0; }

// A ground observer at altitude h0 looking at the given elevation, to where the ray leaves radius
// R + top (the geometry of the published figures: x = R/H, zenith angle 90° − elevation).
AirmassRay groundRay(double h0, double elevationDegrees, double H, double top = 1000.0)
{
    glm::dvec3 origin(0.0, 0.0, kR + h0);
    glm::dvec3 d(std::cos(radians(elevationDegrees)), 0.0, std::sin(radians(elevationDegrees)));
    double b = glm::dot(origin, d);
    double c = glm::dot(origin, origin) - (kR + top) * (kR + top);
    return {origin, d, 0.0, -b + std::sqrt(b * b - c), H, kR};
}

double relative(double value, double reference) { return std::abs(value - reference) / std::abs(reference); }

double evaluate(const char* method, const AirmassRay& ray, AirmassPrecision precision = AirmassPrecision::Float64)
{
    return evaluateAirmass(*findAirmassMethod(method), ray, precision);
}

// ---- exact reference ----

TEST(ScaledBesselK1, SeriesMatchesStandardLibraryAndChapmanValue)
{
    for (double x : {100.0, 300.0, 499.0}) {
        double term = 1.0, sum = 1.0; // series evaluated here at x below the switch
        for (int k = 1; k < 30; ++k) {
            term *= (4.0 - (2.0 * k - 1.0) * (2.0 * k - 1.0)) / (8.0 * k * x);
            sum += term;
        }
        EXPECT_NEAR(std::sqrt(M_PI / (2.0 * x)) * sum / scaledBesselK1(x), 1.0, 1e-12) << x;
    }
    EXPECT_NEAR(scaledBesselK1(500.0 - 1e-9) / scaledBesselK1(500.0), 1.0, 1e-11);
    EXPECT_NEAR(796.375 * scaledBesselK1(796.375), 35.38532, 5e-6); // reference.md
}

TEST(ExactAirmass, ChapmanValuesOfReference)
{
    const double x = 796.375; // R = 6371 km, H = 8 km
    EXPECT_NEAR(exactChapman(x, radians(90.0)), 35.38532, 5e-6);
    EXPECT_NEAR(exactChapman(x, radians(60.0)), 1.99258, 5e-6);
    EXPECT_NEAR(exactChapman(x, radians(85.0)), 10.14003, 5e-6);
    EXPECT_NEAR(exactChapman(x, radians(90.0)) / (x * scaledBesselK1(x)), 1.0, 1e-10);
}

TEST(ExactAirmass, HorizontalRayFromSurfaceIsHxExpxK1)
{
    for (double H : {1.0, 8.0, 50.0, 500.0}) {
        double x = kR / H;
        AirmassRay ray{{0.0, 0.0, kR}, {1.0, 0.0, 0.0}, 0.0, 400.0 * std::sqrt(kR * H) + 400.0 * H, H, kR};
        EXPECT_NEAR(exactAirmass(ray) / (H * x * scaledBesselK1(x)), 1.0, 1e-10) << H;
    }
}

TEST(ExactAirmass, VerticalRayIsDifferenceOfExponentials)
{
    for (double H : {0.5, 8.0, 50.0}) {
        for (auto [h0, h1] : {std::pair{0.0, 0.001}, {0.0, 100.0}, {3.0, 5000.0}, {-20.0, 1e6}}) {
            AirmassRay ray{{0.0, kR + h0, 0.0}, {0.0, 2.0, 0.0}, 0.0, h1 - h0, H, kR};
            double expected = H * (std::exp(-h0 / H) - std::exp(-h1 / H));
            EXPECT_NEAR(exactAirmass(ray) / expected, 1.0, 1e-10) << H << " " << h0 << " " << h1;
        }
    }
}

TEST(ExactAirmass, AdditiveOverSplitSegmentsIncludingGrazingAndSpikes)
{
    // A limb ray from geostationary orbit with a 1 m tangent height and H = 1 km: a narrow spike on a
    // 42000 km segment. Splitting anywhere must not change the sum beyond 1e-10.
    double y = kR + 0.001;
    double distance = kR + 35786.0;
    glm::dvec3 origin(0.0, 0.0, distance);
    glm::dvec3 d(y / distance, 0.0, -std::sqrt(1.0 - (y / distance) * (y / distance)));
    double tTangent = std::sqrt(distance * distance - y * y);
    for (double H : {1.0, 8.0}) {
        double whole = exactAirmass(origin, d, 0.0, 2.0 * tTangent, H, kR);
        for (double split : {tTangent - 3000.0, tTangent - 1.0, tTangent + 0.0005, tTangent + 700.0}) {
            double sum = exactAirmass(origin, d, 0.0, split, H, kR) + exactAirmass(origin, d, split, 2.0 * tTangent, H, kR);
            EXPECT_NEAR(sum / whole, 1.0, 1e-10) << H << " " << split;
        }
        // Both halves of a tangent ray through the same tangent point: symmetric.
        EXPECT_NEAR(exactAirmass(origin, d, 0.0, tTangent, H, kR) / exactAirmass(origin, d, tTangent, 2.0 * tTangent, H, kR),
                    1.0, 1e-10);
    }
}

// ---- published error figures (docs/airmass.md gives the geometry) ----

TEST(PublishedFigures, WinitzkiErfMaxRelativeError)
{
    double worst = 0.0, worstX = 0.0;
    for (double x = 0.001; x < 6.0; x += 0.001) {
        double error = std::abs(test64::winitzkiErf(x) - std::erf(x)) / std::erf(x);
        if (error > worst) { worst = error; worstX = x; }
    }
    EXPECT_NEAR(worst, 3.5e-4, 0.05e-4);
    EXPECT_NEAR(worstX, 1.32, 0.05);
}

// Lawlor's parabola with an accurate erf (lawlor-erfcx, double): ground observer at 0 km, H = 8 km,
// elevations 0–90° every 0.5°, to 1000 km altitude.
TEST(PublishedFigures, LawlorParabolaWithExactErfWithin2p6e4)
{
    double worst = 0.0;
    for (double elevation = 0.0; elevation <= 90.0; elevation += 0.5) {
        AirmassRay ray = groundRay(0.0, elevation, 8.0);
        worst = std::max(worst, relative(evaluate("lawlor-erfcx", ray), exactAirmass(ray)));
    }
    EXPECT_LE(worst, 2.6e-4);
    EXPECT_GE(worst, 1e-4);
}

TEST(PublishedFigures, LawlorWinitzkiIs6p2PercentLowAt10Degrees)
{
    AirmassRay ray = groundRay(0.0, 10.0, 8.0);
    for (AirmassPrecision precision : {AirmassPrecision::Float32, AirmassPrecision::Float64}) {
        EXPECT_NEAR(evaluate("lawlor-winitzki", ray, precision) / exactAirmass(ray) - 1.0, -0.062, 0.001);
    }
}

// NOT the published "at worst about 1.5% low": measured from 1 m above the ground to its own top of the
// atmosphere (6H, H = 8 km), 0–10° elevation, it is −0.3% at 0° and up to +2.6% high near 3°
// (docs/airmass.md). The test pins what we measured.
TEST(PublishedFigures, TectonicsQuadraticMeasuredBandNearTheHorizon)
{
    for (double elevation = 0.0; elevation <= 10.0; elevation += 0.25) {
        AirmassRay ray = groundRay(0.001, elevation, 8.0, 6.0 * 8.0); // 1 m up: from 0 m it reports "obstructed"
        double error = evaluate("tectonics-quadratic", ray) / exactAirmass(ray) - 1.0;
        EXPECT_GE(error, -0.005) << elevation;
        EXPECT_LE(error, 0.027) << elevation;
    }
}

// Schüler's Ch (as distributed, c = √x) is low everywhere between zenith angles 80° and 89°:
// 14% at 80°, up to 24% at 89° (docs/airmass.md).
TEST(PublishedFigures, SchuelerIsLowBetween80And89Degrees)
{
    double worst = 0.0;
    for (double zenith = 80.0; zenith <= 89.0; zenith += 0.5) {
        AirmassRay ray = groundRay(0.0, 90.0 - zenith, 8.0);
        double error = evaluate("chapman-schueler", ray) / exactAirmass(ray) - 1.0;
        EXPECT_LT(error, -0.13) << zenith;
        worst = std::min(worst, error);
    }
    EXPECT_NEAR(evaluate("chapman-schueler", groundRay(0.0, 10.0, 8.0)) / exactAirmass(groundRay(0.0, 10.0, 8.0)) - 1.0,
                -0.14, 0.005);
    EXPECT_GT(worst, -0.25);
}

TEST(PublishedFigures, HdrpFitWithin0p34PercentOfChapman)
{
    for (double zenith = 0.0; zenith <= 90.0; zenith += 1.0) {
        AirmassRay ray = groundRay(0.0, 90.0 - zenith, 8.0);
        EXPECT_LE(relative(evaluate("chapman-hdrp", ray), exactAirmass(ray)), 0.0034) << zenith;
    }
}

// ---- the default method over the sweep ----

TEST(AirmassSweep, DefaultMethodMeetsAccuracyGoal)
{
    std::vector<MethodAccuracy> rows = measureAirmassAccuracy(airmassAccuracyRays(), false);
    for (const MethodAccuracy& row : rows) {
        if (row.method != kDefaultAirmassMethod) continue;
        EXPECT_EQ(row.nonFiniteCount, 0u);
        if (row.precision == AirmassPrecision::Float64) {
            EXPECT_LE(row.maxRelativeError, 1e-4);
        }
        // float32: radii near 6371 km are quantised to 0.49 m, i.e. 5e-4 of H = 1 km per end point.
        if (row.precision == AirmassPrecision::Float32) {
            EXPECT_LE(row.maxRelativeError, 1.5e-3);
        }
        EXPECT_LE(row.rmsRelativeError, 2e-4);
    }
}

// ---- definitions and extreme cases ----

TEST(AirmassDefinitions, SignedZeroLengthZeroDirectionNonUnitDirection)
{
    AirmassRay ray = groundRay(1.0, 3.0, 8.0);
    AirmassRay reversed = ray;
    std::swap(reversed.t0, reversed.t1);
    AirmassRay scaled = ray;
    scaled.direction *= 7.5;
    AirmassRay empty = ray;
    empty.t1 = empty.t0 = 12.0;
    AirmassRay noDirection = ray;
    noDirection.direction = glm::dvec3(0.0);
    for (const AirmassMethod& method : airmassMethods()) {
        for (AirmassPrecision precision : {AirmassPrecision::Float32, AirmassPrecision::Float64}) {
            double value = evaluateAirmass(method, ray, precision);
            EXPECT_EQ(evaluateAirmass(method, reversed, precision), -value) << method.name;
            EXPECT_NEAR(evaluateAirmass(method, scaled, precision) / value, 1.0, 1e-4) << method.name;
            EXPECT_EQ(evaluateAirmass(method, empty, precision), 0.0) << method.name;
            EXPECT_EQ(evaluateAirmass(method, noDirection, precision), 0.0) << method.name;
        }
    }
}

// Rays where the default method and the march must stay finite, and the default close to exact.
TEST(AirmassExtremes, FiniteEverywhereAndDefaultCloseToExact)
{
    const double far = 1e6;
    const double onlyFinite = INFINITY; // deep inside the planet (density capped at e^60) or below 1e-30 km
    std::vector<std::pair<AirmassRay, double>> cases{ // ray, tolerance of the default vs exact (float)
        {{{0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, -7000.0, 7000.0, 8.0, kR}, onlyFinite},    // through the centre
        {{{0.0, 0.0, 0.0}, {1.0, 2.0, 3.0}, 0.0, 20.0, 8.0, kR}, onlyFinite},          // origin at the centre
        {{{0.0, 0.0, far}, {0.0, 0.0, -1.0}, 0.0, far - kR, 8.0, kR}, 1e-3},            // viewer at 1e6 km
        {{{kR + 0.001, 0.0, 0.0}, {0.0, 1.0, 0.0}, -3000.0, 3000.0, 8.0, kR}, 1e-3},    // tangent at 1 m
        {{{kR + 5.0, 0.0, 0.0}, {0.3, 1.0, 0.0}, 0.0, 9000.0, 0.05, kR}, onlyFinite},   // H ≪ segment: e^-100
        {{{kR + 0.2, 0.0, 0.0}, {0.0, 1.0, 0.0}, 0.0, 9000.0, 0.05, kR}, 1e-2},         // H ≪ segment, grazing
        {{{kR + 5.0, 0.0, 0.0}, {0.3, 1.0, 0.0}, 0.0, 9000.0, 1e5, kR}, 1e-3},          // H ≫ R
        {{{kR - 50.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 0.0, 500.0, 8.0, kR}, 1e-3},          // inside the planet
    };
    for (const auto& [ray, tolerance] : cases) {
        double exact = exactAirmass(ray);
        EXPECT_TRUE(std::isfinite(exact));
        for (const char* name : {kDefaultAirmassMethod, "march16"}) {
            for (AirmassPrecision precision : {AirmassPrecision::Float32, AirmassPrecision::Float64}) {
                EXPECT_TRUE(std::isfinite(evaluate(name, ray, precision))) << name;
            }
        }
        EXPECT_LE(relative(evaluate(kDefaultAirmassMethod, ray, AirmassPrecision::Float32), exact), tolerance)
            << ray.origin.x << " " << ray.scaleHeight;
    }
}

// Values just either side of each switch of the default method agree to 1e-4.
TEST(AirmassSwitches, ContinuousAcrossSwitches)
{
    auto check = [](AirmassRay below, AirmassRay above) {
        for (AirmassPrecision precision : {AirmassPrecision::Float32, AirmassPrecision::Float64}) {
            EXPECT_LE(relative(evaluate(kDefaultAirmassMethod, below, precision),
                               evaluate(kDefaultAirmassMethod, above, precision)), 1e-4);
        }
    };
    // Short-segment form at |t1 − t0| = H.
    AirmassRay ray = groundRay(2.0, 4.0, 8.0);
    AirmassRay below = ray, above = ray;
    below.t1 = 8.0 * (1 - 1e-6);
    above.t1 = 8.0 * (1 + 1e-6);
    check(below, above);
    // Gauss–Legendre piece at a rise of one scale height: vertical ray from 2 km, rise = t1/H.
    AirmassRay vertical{{0.0, 0.0, kR + 2.0}, {0.0, 0.0, 1.0}, -20.0, 8.0, 8.0, kR};
    below = above = vertical;
    below.t1 = 8.0 * (1 - 1e-6);
    above.t1 = 8.0 * (1 + 1e-6);
    check(below, above);
    // Huestis' integral below r/H = 50: a horizontal ray from the surface with H = R/50.
    AirmassRay horizontal{{0.0, 0.0, kR}, {1.0, 0.0, 0.0}, 0.0, 5000.0, kR / 50.0, kR};
    below = above = horizontal;
    below.scaleHeight *= 1 + 1e-6;
    above.scaleHeight *= 1 - 1e-6;
    check(below, above);
}

// ---- command line ----

int runCli(std::vector<std::string> args, const std::string& input, std::string& out, std::string& err)
{
    std::vector<char*> argv;
    for (std::string& arg : args) argv.push_back(arg.data());
    std::istringstream in(input);
    std::ostringstream outStream, errStream;
    int status = runAirmassCommand(int(argv.size()), argv.data(), in, outStream, errStream);
    out = outStream.str();
    err = errStream.str();
    return status;
}

TEST(AirmassCli, ListsMethodsAndComputes)
{
    std::string out, err;
    ASSERT_EQ(runCli({"airmass", "--method", "list"}, "", out, err), 0);
    EXPECT_NE(out.find("exact\n"), std::string::npos);
    EXPECT_NE(out.find(std::string(kDefaultAirmassMethod) + "\n"), std::string::npos);
    std::string input = "ox,oy,oz,dx,dy,dz,t0,t1,H,R\n\n0,6371,0,0,1,0,0,100,8,6371\n0,6371,0,0,1,0,100,0,8,6371\n";
    ASSERT_EQ(runCli({"airmass", "--method", "exact"}, input, out, err), 0);
    double expected = 8.0 * (1.0 - std::exp(-100.0 / 8.0));
    std::istringstream lines(out);
    double first = 0.0, second = 0.0;
    lines >> first >> second;
    EXPECT_NEAR(first, expected, 1e-9);
    EXPECT_NEAR(second, -expected, 1e-9);
    ASSERT_EQ(runCli({"airmass"}, input, out, err), 0); // the default, float32
    std::istringstream defaultLines(out);
    defaultLines >> first;
    EXPECT_NEAR(first, expected, 1e-5 * expected);
    ASSERT_EQ(runCli({"airmass", "--help"}, "", out, err), 0);
    EXPECT_NE(out.find("--method"), std::string::npos);
}

TEST(AirmassCli, MalformedLinesFailWithLineNumber)
{
    for (const std::string& bad : {std::string("1,2,3\n"), std::string("0,6371,0,0,1,0,0,x,8,6371\n"),
                                   std::string("0,6371,0,0,1,0,0,nan,8,6371\n"), std::string("0,6371,0,0,1,0,0,inf,8,6371\n"),
                                   std::string("0,6371,0,0,1,0,0,1,0,6371\n"), std::string("0,6371,0,0,1,0,0,1,8,-1\n"),
                                   std::string("0,6371,0,0,1,0,0,1,8,6371,\n")}) {
        std::string out, err;
        EXPECT_EQ(runCli({"airmass"}, "0,6371,0,0,1,0,0,100,8,6371\n\n" + bad, out, err), 2) << bad;
        EXPECT_EQ(out, "") << bad;
        EXPECT_NE(err.find("line 3"), std::string::npos) << err;
    }
    std::string out, err;
    EXPECT_EQ(runCli({"airmass", "--method", "nope"}, "", out, err), 2);
}

} // namespace
} // namespace aurorawall
