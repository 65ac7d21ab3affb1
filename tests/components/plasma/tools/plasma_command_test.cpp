// `aurorawall plasma verify` (components/plasma/tools/plasma_command.h) called in the test's process:
// time steps and spacings outside their ranges are errors naming the option, every number printed
// finite over the options' ranges.
#include "common/finite_cells.h"
#include "common/run_in_process.h"
#include "components/plasma/simulation/verify_cases.h"
#include "components/plasma/tools/plasma_command.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace aurorawall::components::plasma::tools {
namespace {

namespace pic = aurorawall::components::plasma::simulation;
using Result = test::CommandOutput;
using test::above;
using test::below;
using test::exactly;
using test::lines;
using test::nonFiniteCell;

Result runPlasma(std::vector<std::string> options)
{
    return test::runInProcess(runPlasmaCommand, "plasma", std::move(options));
}

// Time steps and spacings where a case cannot measure are usage errors naming the option: at
// --wp-dt 1e-300 the step count overflowed and langmuir printed NaN, exb did at --wc-dt 1e300 and
// 1e-300, heating at --dx-lambda-d 1e300 (and failed with no option named at 5e-324).
TEST(PlasmaCommand, TimeStepsAndSpacingsOutsideTheirRangesNameTheOption)
{
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
        {{"--case", "langmuir", "--wp-dt", "1e-300"}, "--wp-dt must be in [0.01, 2)"},
        {{"--case", "langmuir", "--wp-dt", "0.0099999"}, "--wp-dt must be in [0.01, 2)"},
        {{"--case", "exb", "--wc-dt", "1e300"}, "--wc-dt must be in [1e-06, 1000000]"},
        {{"--case", "exb", "--wc-dt", "1e-300"}, "--wc-dt must be in [1e-06, 1000000]"},
        {{"--case", "heating", "--dx-lambda-d", "1e300"}, "--dx-lambda-d must be in [0.01, 100]"},
        {{"--case", "heating", "--dx-lambda-d", "5e-324"}, "--dx-lambda-d must be in [0.01, 100]"},
    };
    for (const auto& [words, expected] : cases) {
        std::vector<std::string> args = {"verify"};
        args.insert(args.end(), words.begin(), words.end());
        const Result r = runPlasma(args);
        EXPECT_EQ(r.status, 2) << expected;
        EXPECT_TRUE(r.out.empty()) << r.out;
        EXPECT_EQ(r.err.rfind("aurorawall plasma: " + expected, 0), 0u) << r.err;
        EXPECT_EQ(lines(r.err).size(), 1u) << r.err;
    }
}

// However long the action, the error that quotes it is one short line with its start and length.
TEST(PlasmaCommand, ErrorsQuotingAHugeActionStayOneShortLine)
{
    const std::string error = runPlasma({std::string(1 << 20, 'w')}).err;
    EXPECT_EQ(lines(error).size(), 1u);
    EXPECT_LT(error.size(), 400u);
    EXPECT_NE(error.find("(1048576 bytes)"), std::string::npos) << error.substr(0, 400);
}

Result plasmaVerify(const std::vector<std::string>& options)
{
    std::vector<std::string> words = {"plasma", "verify"};
    words.insert(words.end(), options.begin(), options.end());
    return test::runInProcess(runPlasmaCommand, words);
}

void expectUsageError(const std::vector<std::string>& options, const std::string& option)
{
    const Result r = plasmaVerify(options);
    EXPECT_EQ(r.status, 2) << options.back();
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_NE(r.err.find(option), std::string::npos) << r.err;
}

TEST(FiniteOutput, PlasmaVerifyEveryOptionOverItsRange)
{
    const auto expectFinite = [](const std::vector<std::string>& options) {
        const Result r = plasmaVerify(options);
        std::string given;
        for (const std::string& o : options) given += o + " ";
        EXPECT_EQ(r.status, 0) << given << r.err;
        EXPECT_EQ(nonFiniteCell(r.out), "") << given;
    };
    // --wc-dt: boris and exb (1000 steps each, whatever the step).
    for (const char* name : {"boris", "exb"}) {
        for (const double wcDt : {pic::kMinVerifyWcDt, above(pic::kMinVerifyWcDt), 1.0, 100.0,
                                  below(pic::kMaxVerifyWcDt), pic::kMaxVerifyWcDt})
            expectFinite({"--case", name, "--wc-dt", exactly(wcDt)});
        for (const double wcDt : {below(pic::kMinVerifyWcDt), above(pic::kMaxVerifyWcDt), 0.0, -0.0, 1e-300, 1e300})
            expectUsageError({"--case", name, "--wc-dt", exactly(wcDt)}, "--wc-dt");
    }
    // --dx-lambda-d: heating.
    for (const double dx : {pic::kMinHeatingDxDebye, above(pic::kMinHeatingDxDebye), below(pic::kMaxHeatingDxDebye),
                            pic::kMaxHeatingDxDebye})
        expectFinite({"--case", "heating", "--dx-lambda-d", exactly(dx)});
    for (const double dx : {below(pic::kMinHeatingDxDebye), above(pic::kMaxHeatingDxDebye), 0.0, -0.0, 1e300})
        expectUsageError({"--case", "heating", "--dx-lambda-d", exactly(dx)}, "--dx-lambda-d");
    // --wp-dt: every case that takes it just below 2, the coarsest step (few steps, so quick); its lower
    // end below, on smaller runs of the same cases. --k-lambda-d: its range is refused outside.
    for (const char* name : {"langmuir", "langmuir-2d", "langmuir-3d", "two-stream", "energy", "heating", "landau"})
        expectFinite({"--case", name, "--wp-dt", exactly(below(2.0))});
    for (const double wpDt : {below(pic::kMinVerifyWpDt), 2.0, 0.0, -0.0, 1e-300})
        expectUsageError({"--case", "langmuir", "--wp-dt", exactly(wpDt)}, "--wp-dt");
    for (const double k : {below(pic::kLandauMinKDebye), above(pic::kLandauMaxKDebye), 0.0, -0.0})
        expectUsageError({"--case", "landau", "--k-lambda-d", exactly(k)}, "--k-lambda-d");
}

// The cases at the lower end of ω_pΔt (thousands of steps: the command's full sizes take minutes
// there) and at both ends of kλ_D, on small grids and particle counts.
TEST(FiniteOutput, PlasmaCasesAtTheEndsOfTheirRangesOnSmallRuns)
{
    const auto expectFinite = [](const std::vector<pic::VerifyRow>& rows, const std::string& what) {
        for (const pic::VerifyRow& row : rows) {
            EXPECT_TRUE(std::isfinite(row.measured)) << what << " " << row.parameter;
            if (row.expected) {
                EXPECT_TRUE(std::isfinite(row.relativeError())) << what << " " << row.parameter;
            }
        }
    };
    const double lowest = pic::kMinVerifyWpDt;
    expectFinite(pic::verifyLangmuir2D(lowest, 8), "langmuir-2d");
    expectFinite(pic::verifyLangmuir3D(lowest, 4), "langmuir-3d");
    expectFinite(pic::verifyHeating(lowest, 1.0, 1, pic::cpuDevice(), 1), "heating");
    expectFinite(pic::verifyLandau(lowest, 0.5, 1 << 12), "landau");
    for (const double k : {pic::kLandauMinKDebye, pic::kLandauMaxKDebye})
        expectFinite(pic::verifyLandau(0.2, k, 1 << 14), "landau k lambda_D " + exactly(k));
}

} // namespace
} // namespace aurorawall::components::plasma::tools
