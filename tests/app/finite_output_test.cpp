// No command prints NaN or Inf with exit status 0: each numeric option and CSV field of airmass, mie,
// tables deposition and plasma verify swept over its accepted range (both ends, the doubles next to
// them inside, ±0 where accepted, values between), every number printed finite; a value just outside
// the range an error naming the option (exit status 2) or the CSV field and line (exit status 1).
// The commands are called directly, not as processes.
#include "app/airmass_command.h"
#include "app/mie_command.h"
#include "app/plasma_command.h"
#include "app/tables_command.h"
#include "run_in_process.h"
#include "atmosphere/airmass.h"
#include "components/plasma/simulation/verify_cases.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace aurorawall::app {
namespace {

using Output = test::CommandOutput;
using test::runInProcess;

Output airmass(const std::string& method, const std::string& input)
{
    std::istringstream in(input);
    return runInProcess([&](int argc, char** argv, std::ostream& out, std::ostream& err) { return runAirmassCommand(argc, argv, in, out, err); },
               {"airmass", "--method", method});
}

// Decimal text that reads back as exactly this double (17 significant digits).
std::string exactly(double value)
{
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

// The first cell of the output (split at commas and line ends) that reads as a number but is not
// finite, or "" when there is none.
std::string nonFiniteCell(const std::string& output)
{
    std::string cell;
    for (std::size_t i = 0; i <= output.size(); ++i) {
        if (i < output.size() && output[i] != ',' && output[i] != '\n') {
            cell += output[i];
            continue;
        }
        char* end = nullptr;
        const double value = std::strtod(cell.c_str(), &end);
        if (!cell.empty() && *end == '\0' && !std::isfinite(value)) return cell;
        cell.clear();
    }
    return "";
}

const double kFloatMax = FLT_MAX, kFloatTiny = FLT_TRUE_MIN;
double above(double x) { return std::nextafter(x, INFINITY); }
double below(double x) { return std::nextafter(x, -INFINITY); }

// ---- airmass: every field, every method ----

struct FieldRange {
    std::vector<double> inside, outside;
};

// Lengths and directions: any float; H from float's smallest positive number; R >= 0.
const FieldRange kAnyFloat = {{-kFloatMax, -1e30, -6371.0, -1.0, -FLT_MIN, -kFloatTiny, -0.0, 0.0, kFloatTiny, FLT_MIN,
                               1e-30, 1.0, 6371.0, 1e30, kFloatMax},
                              {below(-kFloatMax), above(kFloatMax), -1e308, 1e308}};
const FieldRange kScaleHeight = {{kFloatTiny, above(kFloatTiny), FLT_MIN, 1e-30, 1.0, 8.0, 1e30, kFloatMax},
                                 {below(kFloatTiny), 1e-320, 0.0, -0.0, -8.0, above(kFloatMax)}};
const FieldRange kRadius = {{-0.0, 0.0, kFloatTiny, 1.0, 6371.0, 1e30, kFloatMax},
                            {-kFloatTiny, -1.0, above(kFloatMax)}};

TEST(FiniteOutput, AirmassEveryFieldOverItsRange)
{
    const char* const names[] = {"ox", "oy", "oz", "dx", "dy", "dz", "t0", "t1", "H", "R"};
    // Rays the values are put into: from the ground at 11° elevation, a limb from 400 km, through the
    // planet's centre.
    const std::vector<std::vector<double>> rays = {{0.0, 6371.0, 0.0, 1.0, 0.2, 0.0, 0.0, 100.0, 8.0, 6371.0},
                                                   {6771.0, 0.0, 0.0, -0.3, 1.0, 0.0, 0.0, 5000.0, 8.0, 6371.0},
                                                   {0.0, 0.0, 0.0, 0.0, 0.0, 1.0, -7000.0, 7000.0, 8.0, 6371.0}};
    for (const AirmassMethod& method : airmassMethods()) {
        // The default and the reference give a finite value for every accepted ray; the others may
        // refuse a ray they give none for (an error naming the line), never print a NaN.
        const bool alwaysFinite = method.name == kDefaultAirmassMethod || method.name == "exact";
        for (int field = 0; field < 10; ++field) {
            const FieldRange& range = field == 8 ? kScaleHeight : field == 9 ? kRadius : kAnyFloat;
            for (const std::vector<double>& ray : rays)
                for (const bool inside : {true, false})
                    for (const double value : inside ? range.inside : range.outside) {
                        std::string line;
                        for (int i = 0; i < 10; ++i) line += (i ? "," : "") + exactly(i == field ? value : ray[i]);
                        const Output r = airmass(method.name, line + "\n");
                        const std::string where = method.name + " " + names[field] + " = " + exactly(value) + ": " + line;
                        EXPECT_EQ(nonFiniteCell(r.out), "") << where;
                        EXPECT_NE(r.status, 2) << where << " " << r.err;
                        if (!inside) {
                            EXPECT_EQ(r.status, 1) << where;
                            EXPECT_NE(r.err.find("line 1: field " + std::to_string(field + 1) + " (" + names[field] + ")"),
                                      std::string::npos) << where << " " << r.err;
                        } else if (r.status == 0) {
                            EXPECT_EQ(r.out.find('\n'), r.out.size() - 1) << where << " " << r.out;
                        } else {
                            EXPECT_FALSE(alwaysFinite) << where << " " << r.err;
                            EXPECT_NE(r.err.find("line 1: " + method.name + " gives no finite airmass"), std::string::npos)
                                << where << " " << r.err;
                        }
                    }
        }
    }
}

// ---- mie: n, k, x and the angles ----

Output mie(const std::string& n, const std::string& k, const std::string& x, const std::string& angles)
{
    return runInProcess(runMieCommand, {"mie", "--n", n, "--k", k, "--x", x, "--angles-deg", angles});
}

TEST(FiniteOutput, MieEveryOptionOverItsRange)
{
    // n in [1, 10], k in [0, 100], x in [1e-4, 1e5]; every angle in [0, 180].
    const std::vector<std::vector<double>> inside = {
        {1.0, above(1.0), 1.33, below(10.0), 10.0},
        {-0.0, 0.0, 4.9e-324, 1e-300, 1e-5, 1.0, below(100.0), 100.0},
        {1e-4, above(1e-4), 0.5, 10.0, below(1e5), 1e5}};
    const std::vector<std::vector<double>> outside = {{below(1.0), above(10.0), 0.0, -1.0, 1e308},
                                                      {-4.9e-324, above(100.0), 1e308},
                                                      {below(1e-4), above(1e5), 0.0, -0.0, 4.9e-324}};
    const char* const options[] = {"--n", "--k", "--x"};
    const std::string angles = "-0,0,4.9e-324,1e-300,1,90,179.99999999999997,180";
    // The other options at the ends of their ranges too.
    const std::vector<std::vector<double>> bases = {{1.33, 1e-5, 10.0}, {1.0, 0.0, 1e-4}, {10.0, 100.0, 1e5}};
    for (int option = 0; option < 3; ++option)
        for (const std::vector<double>& base : bases)
            for (const bool isInside : {true, false})
                for (const double value : isInside ? inside[option] : outside[option]) {
                    std::vector<double> v = base;
                    v[option] = value;
                    const Output r = mie(exactly(v[0]), exactly(v[1]), exactly(v[2]), angles);
                    const std::string where = std::string(options[option]) + " " + exactly(value) + " (n " +
                                              exactly(v[0]) + ", k " + exactly(v[1]) + ", x " + exactly(v[2]) + ")";
                    EXPECT_EQ(nonFiniteCell(r.out), "") << where;
                    if (isInside) {
                        EXPECT_EQ(r.status, 0) << where << " " << r.err;
                    } else {
                        EXPECT_EQ(r.status, 2) << where;
                        EXPECT_NE(r.err.find(options[option]), std::string::npos) << where << " " << r.err;
                    }
                }
    for (const std::string& angle : {std::string("-4.9e-324"), exactly(above(180.0)), std::string("1e999"), std::string("-1")}) {
        const Output r = mie("1.33", "0", "1", "0," + angle);
        EXPECT_EQ(r.status, 2) << angle;
        EXPECT_NE(r.err.find("--angles-deg"), std::string::npos) << r.err;
    }
}

// ---- tables deposition: --energy-kev in [0.01, 1000] ----

TEST(FiniteOutput, TablesEnergyOverItsRange)
{
    for (const bool maxwellian : {false, true}) {
        for (const double energy : {0.01, above(0.01), 1.0, 30.0, below(1000.0), 1000.0}) {
            std::vector<std::string> words = {"tables", "deposition", "--energy-kev", exactly(energy)};
            if (maxwellian) words.push_back("--maxwellian");
            const Output r = runInProcess(runTablesCommand, words);
            EXPECT_EQ(r.status, 0) << energy << " " << r.err;
            EXPECT_EQ(nonFiniteCell(r.out), "") << energy;
        }
        for (const double energy : {below(0.01), above(1000.0), 0.0, -0.0, 1e308}) {
            const Output r = runInProcess(runTablesCommand, std::vector<std::string>{"tables", "deposition", "--energy-kev", exactly(energy)});
            EXPECT_EQ(r.status, 2) << energy;
            EXPECT_NE(r.err.find("--energy-kev"), std::string::npos) << r.err;
        }
    }
}

// ---- plasma verify: --wp-dt, --wc-dt, --dx-lambda-d, --k-lambda-d ----

Output plasmaVerify(const std::vector<std::string>& options)
{
    std::vector<std::string> words = {"plasma", "verify"};
    words.insert(words.end(), options.begin(), options.end());
    return runInProcess(runPlasmaCommand, words);
}

void expectUsageError(const std::vector<std::string>& options, const std::string& option)
{
    const Output r = plasmaVerify(options);
    EXPECT_EQ(r.status, 2) << options.back();
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_NE(r.err.find(option), std::string::npos) << r.err;
}

TEST(FiniteOutput, PlasmaVerifyEveryOptionOverItsRange)
{
    const auto expectFinite = [](const std::vector<std::string>& options) {
        const Output r = plasmaVerify(options);
        std::string given;
        for (const std::string& o : options) given += o + " ";
        EXPECT_EQ(r.status, 0) << given << r.err;
        EXPECT_EQ(nonFiniteCell(r.out), "") << given;
    };
    // --wc-dt: boris and exb (1000 steps each, whatever the step).
    for (const char* name : {"boris", "exb"}) {
        for (const double wcDt : {plasma::kMinVerifyWcDt, above(plasma::kMinVerifyWcDt), 1.0, 100.0,
                                  below(plasma::kMaxVerifyWcDt), plasma::kMaxVerifyWcDt})
            expectFinite({"--case", name, "--wc-dt", exactly(wcDt)});
        for (const double wcDt : {below(plasma::kMinVerifyWcDt), above(plasma::kMaxVerifyWcDt), 0.0, -0.0, 1e-300, 1e300})
            expectUsageError({"--case", name, "--wc-dt", exactly(wcDt)}, "--wc-dt");
    }
    // --dx-lambda-d: heating.
    for (const double dx : {plasma::kMinHeatingDxDebye, above(plasma::kMinHeatingDxDebye), below(plasma::kMaxHeatingDxDebye),
                            plasma::kMaxHeatingDxDebye})
        expectFinite({"--case", "heating", "--dx-lambda-d", exactly(dx)});
    for (const double dx : {below(plasma::kMinHeatingDxDebye), above(plasma::kMaxHeatingDxDebye), 0.0, -0.0, 1e300})
        expectUsageError({"--case", "heating", "--dx-lambda-d", exactly(dx)}, "--dx-lambda-d");
    // --wp-dt: every case that takes it just below 2, the coarsest step (few steps, so quick); its lower
    // end below, on smaller runs of the same cases. --k-lambda-d: its range is refused outside.
    for (const char* name : {"langmuir", "langmuir-2d", "langmuir-3d", "two-stream", "energy", "heating", "landau"})
        expectFinite({"--case", name, "--wp-dt", exactly(below(2.0))});
    for (const double wpDt : {below(plasma::kMinVerifyWpDt), 2.0, 0.0, -0.0, 1e-300})
        expectUsageError({"--case", "langmuir", "--wp-dt", exactly(wpDt)}, "--wp-dt");
    for (const double k : {below(plasma::kLandauMinKDebye), above(plasma::kLandauMaxKDebye), 0.0, -0.0})
        expectUsageError({"--case", "landau", "--k-lambda-d", exactly(k)}, "--k-lambda-d");
}

// The cases at the lower end of ω_pΔt (thousands of steps: the command's full sizes take minutes
// there) and at both ends of kλ_D, on small grids and particle counts.
TEST(FiniteOutput, PlasmaCasesAtTheEndsOfTheirRangesOnSmallRuns)
{
    const auto expectFinite = [](const std::vector<plasma::VerifyRow>& rows, const std::string& what) {
        for (const plasma::VerifyRow& row : rows) {
            EXPECT_TRUE(std::isfinite(row.measured)) << what << " " << row.parameter;
            if (row.expected) {
                EXPECT_TRUE(std::isfinite(row.relativeError())) << what << " " << row.parameter;
            }
        }
    };
    const double lowest = plasma::kMinVerifyWpDt;
    expectFinite(plasma::verifyLangmuir2D(lowest, 8), "langmuir-2d");
    expectFinite(plasma::verifyLangmuir3D(lowest, 4), "langmuir-3d");
    expectFinite(plasma::verifyHeating(lowest, 1.0, 1, plasma::cpuDevice(), 1), "heating");
    expectFinite(plasma::verifyLandau(lowest, 0.5, 1 << 12), "landau");
    for (const double k : {plasma::kLandauMinKDebye, plasma::kLandauMaxKDebye})
        expectFinite(plasma::verifyLandau(0.2, k, 1 << 14), "landau k lambda_D " + exactly(k));
}

} // namespace
} // namespace aurorawall::app
