// `aurorawall mie` (components/glory/tools/mie_command.h) called in the test's process: its values
// against Wiscombe's, its errors one line naming the option, every number finite over its options'
// ranges.
#include "common/finite_cells.h"
#include "common/run_in_process.h"
#include "components/glory/tools/mie_command.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace aurorawall::components::glory::tools {
namespace {

using Result = test::CommandOutput;
using test::above;
using test::below;
using test::exactly;
using test::lines;
using test::nonFiniteCell;

Result runMie(std::vector<std::string> options)
{
    return test::runInProcess(runMieCommand, "mie", std::move(options));
}

std::vector<double> csvNumbers(const std::string& row)
{
    std::vector<double> values;
    std::istringstream in(row);
    for (std::string cell; std::getline(in, cell, ',');) values.push_back(std::strtod(cell.c_str(), nullptr)); // stod throws on subnormals
    return values;
}

// Wiscombe's MIEV0 values for water, m = 1.33 − 1e-5 i, x = 100, through the command line.
TEST(MieCommand, PrintsEfficienciesAndAmplitudes)
{
    Result r = runMie({"--n", "1.33", "--k", "1e-5", "--x", "100", "--angles-deg", "0,1,2.5,180"});
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(r.err.empty());
    const std::vector<std::string> rows = lines(r.out);
    ASSERT_EQ(rows.size(), 8u) << r.out;
    EXPECT_EQ(rows[0], "x,n,k,terms,qext,qsca,qabs,qback,g,s1_0_re,s1_0_im,s1_180_re,s1_180_im");
    const std::vector<double> row = csvNumbers(rows[1]);
    ASSERT_EQ(row.size(), 13u);
    EXPECT_EQ(row[3], 120.0);
    EXPECT_NEAR(row[4], 2.101321, 0.5e-6);
    EXPECT_NEAR(row[5], 2.096594, 0.5e-6);
    EXPECT_NEAR(row[8], 0.868959, 0.5e-6);
    EXPECT_NEAR(row[9], 5253.302, 0.5e-3);
    EXPECT_NEAR(row[10], -124.3188, 0.5e-4);
    EXPECT_NEAR(row[11], -56.59205, 0.5e-5);
    EXPECT_NEAR(row[12], 46.50974, 0.5e-5);
    EXPECT_EQ(rows[2], "");
    EXPECT_EQ(rows[3], "angle_deg,i_parallel,i_perpendicular,s1_re,s1_im,s2_re,s2_im");
    const std::vector<double> forward = csvNumbers(rows[4]), backward = csvNumbers(rows[7]);
    EXPECT_EQ(forward[0], 0.0);
    EXPECT_EQ(forward[3], row[9]);
    EXPECT_EQ(forward[4], row[10]);
    EXPECT_EQ(backward[0], 180.0);
    EXPECT_EQ(backward[3], row[11]);
    EXPECT_EQ(backward[5], -row[11]); // S2(180°) = −S1(180°)
    EXPECT_EQ(csvNumbers(rows[5])[0], 1.0);
    EXPECT_EQ(csvNumbers(rows[6])[0], 2.5);
}

TEST(MieCommand, WithoutAnglesOneBlock)
{
    Result r = runMie({"--n", "1.5", "--k", "0", "--x", "10"});
    ASSERT_EQ(r.status, 0) << r.err;
    ASSERT_EQ(lines(r.out).size(), 2u) << r.out;
    EXPECT_NEAR(csvNumbers(lines(r.out)[1])[4], 2.881999, 0.5e-6);
}

TEST(MieCommand, BadOptionsNameTheOptionAndExit2)
{
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
        {{"--n", "1.33", "--k", "0", "--x", "0"}, "--x"},
        {{"--n", "1.33", "--k", "0", "--x", "-2"}, "--x"},
        {{"--n", "0.9", "--k", "0", "--x", "1"}, "--n"},
        {{"--n", "1.33", "--k", "-0.1", "--x", "1"}, "--k"},
        {{"--n", "nan", "--k", "0", "--x", "1"}, "--n"},
        {{"--n", "1.33", "--k", "0", "--x", "nan"}, "--x"},
        {{"--n", "1.33", "--k", "0", "--x", "inf"}, "--x"},
        {{"--n", "1.33", "--k", "0", "--x"}, "'--x'"},
        {{"--n", "1.33", "--x", "1"}, "'--k'"},
        {{"--n", "1.33", "--k", "0", "--x", "abc"}, "'--x'"},
        {{"--n", "1.33", "--k", "0", "--x", "1", "--angles-deg", "0,,3"}, "--angles-deg"},
        {{"--n", "1.33", "--k", "0", "--x", "1", "--angles-deg", "0,200"}, "--angles-deg"},
        {{"--n", "1.33", "--k", "0", "--x", "1", "--angles-deg", "1;2"}, "--angles-deg"},
        {{"--n", "1.33", "--k", "0", "--x", "1", "--angles-deg", "nan"}, "--angles-deg"},
        {{"--n", "1.33", "--k", "0", "--x", "1", "--bogus"}, "--bogus"},
    };
    for (const auto& [words, named] : cases) {
        Result r = runMie(words);
        EXPECT_EQ(r.status, 2) << named;
        EXPECT_TRUE(r.out.empty()) << named;
        EXPECT_NE(r.err.find(named), std::string::npos) << r.err;
        EXPECT_EQ(r.err.rfind("aurorawall mie: ", 0), 0u) << r.err;
        EXPECT_EQ(lines(r.err).size(), 1u) << r.err;
    }
}

// An angle is any number in [0, 180], a subnormal one too (strtod's ERANGE rejected 4.9e-324).
TEST(MieCommand, SubnormalAnglesAreAngles)
{
    const Result r = runMie({"--n", "1.33", "--k", "0", "--x", "1", "--angles-deg", "4.9e-324,1e-310"});
    ASSERT_EQ(r.status, 0) << r.err;
    ASSERT_EQ(lines(r.out).size(), 6u) << r.out;
    EXPECT_EQ(csvNumbers(lines(r.out)[4])[0], 4.9e-324);
    EXPECT_EQ(csvNumbers(lines(r.out)[5])[0], 1e-310);
    EXPECT_EQ(runMie({"--n", "1.33", "--k", "0", "--x", "1", "--angles-deg", "1e999"}).status, 2);
}

// However long a value, the error that quotes it is one short line with the value's start and length;
// a control character typed into a value stays inside the one line.
TEST(MieCommand, ErrorsQuotingAHugeValueStayOneShortLine)
{
    const std::string huge(1 << 20, '7'), word(1 << 20, 'w');
    const auto expectShort = [&](const std::string& error, const std::string& what) {
        EXPECT_EQ(lines(error).size(), 1u) << what;
        EXPECT_LT(error.size(), 400u) << what;
        EXPECT_NE(error.find("(1048576 bytes)"), std::string::npos) << what << ": " << error.substr(0, 400);
    };
    expectShort(runMie({"--n", "1.33", "--k", "0", "--x", word}).err, "mie --x");
    expectShort(runMie({"--n", "1.33", "--k", "0", "--x", "1", "--angles-deg", huge}).err, "mie --angles-deg");
    expectShort(runMie({"--n", "1.33", "--k", "0", "--x", "1", "--" + word.substr(2), "1"}).err, "unknown option");
    const Result angles = runMie({"--n", "1.33", "--k", "0", "--x", "1", "--angles-deg", "1,2\n,3"});
    EXPECT_EQ(angles.status, 2);
    EXPECT_EQ(lines(angles.err).size(), 1u) << angles.err;
    EXPECT_NE(angles.err.find("'2\\n'"), std::string::npos) << angles.err;
}

Result mie(const std::string& n, const std::string& k, const std::string& x, const std::string& angles)
{
    return test::runInProcess(runMieCommand, {"mie", "--n", n, "--k", k, "--x", x, "--angles-deg", angles});
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
                    const Result r = mie(exactly(v[0]), exactly(v[1]), exactly(v[2]), angles);
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
        const Result r = mie("1.33", "0", "1", "0," + angle);
        EXPECT_EQ(r.status, 2) << angle;
        EXPECT_NE(r.err.find("--angles-deg"), std::string::npos) << r.err;
    }
}

} // namespace
} // namespace aurorawall::components::glory::tools
