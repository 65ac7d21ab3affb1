// No command prints NaN or Inf with exit status 0: each numeric option and CSV field of airmass and
// tables deposition swept over its accepted range (both ends, the doubles next to
// them inside, ±0 where accepted, values between), every number printed finite; a value just outside
// the range an error naming the option (exit status 2) or the CSV field and line (exit status 1).
// The commands are called directly, not as processes.
#include "app/airmass_command.h"
#include "app/tables_command.h"
#include "physics/atmosphere/airmass.h"
#include "common/finite_cells.h"
#include "common/run_in_process.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace aurorawall::app {
namespace {

using Output = test::CommandOutput;
using test::above;
using test::below;
using test::exactly;
using test::nonFiniteCell;
using test::runInProcess;

Output airmass(const std::string& method, const std::string& input)
{
    std::istringstream in(input);
    return runInProcess([&](int argc, char** argv, std::ostream& out, std::ostream& err) { return runAirmassCommand(argc, argv, in, out, err); },
               {"airmass", "--method", method});
}

const double kFloatMax = FLT_MAX, kFloatTiny = FLT_TRUE_MIN;

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
    for (const aurorawall::physics::atmosphere::AirmassMethod& method : aurorawall::physics::atmosphere::airmassMethods()) {
        // The default and the reference give a finite value for every accepted ray; the others may
        // refuse a ray they give none for (an error naming the line), never print a NaN.
        const bool alwaysFinite = method.name == aurorawall::physics::atmosphere::kDefaultAirmassMethod || method.name == "exact";
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

} // namespace
} // namespace aurorawall::app
