#include "aurora/deposition_table.h"
#include "aurora/tables_cli.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace aurorawall::aurora {
namespace {

struct Result {
    int status;
    std::string out, err;
};

Result run(std::vector<std::string> args)
{
    args.insert(args.begin(), "tables");
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    std::ostringstream out, err;
    int status = runTablesCommand(static_cast<int>(argv.size()), argv.data(), out, err);
    return {status, out.str(), err.str()};
}

std::vector<std::string> lines(const std::string& text)
{
    std::vector<std::string> result;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) result.push_back(line);
    return result;
}

TEST(TablesCli, PrintsTheDepositionProfile)
{
    Result r = run({"deposition", "--energy-kev", "5"});
    ASSERT_EQ(r.status, 0) << r.err;
    std::vector<std::string> rows = lines(r.out);
    ASSERT_EQ(rows.size(), 1082u);
    EXPECT_EQ(rows[0], "altitude_km,rate");
    EXPECT_EQ(rows[1].substr(0, 5), "60.0,");
    EXPECT_EQ(rows.back().substr(0, 6), "600.0,");
    // 112.5 km is row 1 + 105.
    double rate = std::stod(rows[106].substr(rows[106].find(',') + 1));
    EXPECT_NEAR(rate / depositionRate(112.5, 5.0, Spectrum::Monoenergetic), 1.0, 1e-9);
}

TEST(TablesCli, MaxwellianFlagSelectsTheSpectrum)
{
    Result r = run({"deposition", "--energy-kev", "2", "--maxwellian"});
    ASSERT_EQ(r.status, 0) << r.err;
    std::vector<std::string> rows = lines(r.out);
    double rate = std::stod(rows[101].substr(rows[101].find(',') + 1)); // 110 km
    EXPECT_NEAR(rate / depositionRate(110.0, 2.0, Spectrum::Maxwellian), 1.0, 1e-9);
}

TEST(TablesCli, BadOptionsNameTheOptionAndExit2)
{
    const std::vector<std::vector<std::string>> bad = {
        {"deposition"}, {"deposition", "--energy-kev", "abc"}, {"deposition", "--energy-kev", "-1"},
        {"deposition", "--energy-kev", "5", "--bogus"}, {"ozone", "--energy-kev", "5"}, {"--energy-kev", "5"}};
    const std::vector<std::string> named = {"energy-kev", "energy-kev", "energy-kev", "bogus", "ozone", "table"};
    for (size_t i = 0; i < bad.size(); ++i) {
        Result r = run(bad[i]);
        EXPECT_EQ(r.status, 2) << i;
        EXPECT_TRUE(r.out.empty()) << i;
        EXPECT_NE(r.err.find(named[i]), std::string::npos) << r.err;
        EXPECT_EQ(lines(r.err).size(), 1u) << r.err;
    }
}

} // namespace
} // namespace aurorawall::aurora
