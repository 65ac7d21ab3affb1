// The command front ends without a GL context or MPI: the command-line convention (src/cli), the
// options of `render`, and the `tables`, `airmass` and `accuracy` commands up to their first GL call.
#include "app/accuracy_command.h"
#include "app/airmass_command.h"
#include "cli/command_line.h"
#include "cli/exit_status.h"
#include "app/control/command.h"
#include "app/cost_map.h"
#include "app/path_recorder.h"
#include "app/render_options.h"
#include "app/tables_command.h"
#include "physics/atmosphere/airmass.h"
#include "cluster/master_clock.h"
#include "common/input_error.h"
#include "components/registry.h"
#include "components/aurora/physics/deposition_table.h"
#include "common/run_in_process.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace aurorawall::app {
namespace {

// argv as the commands see it.
struct Args {
    explicit Args(std::vector<std::string> words) : words_(std::move(words))
    {
        for (std::string& w : words_) pointers_.push_back(w.data());
    }
    int argc() const { return static_cast<int>(pointers_.size()); }
    char** argv() { return pointers_.data(); }

private:
    std::vector<std::string> words_;
    std::vector<char*> pointers_;
};

std::vector<std::string> lines(const std::string& text)
{
    std::vector<std::string> result;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) result.push_back(line);
    return result;
}

// ---- the convention ----

enum class Colour { Red, Green };
const cli::Choices<Colour> kColours = {{"red", Colour::Red}, {"green", Colour::Green}};

TEST(CommandLine, ChoiceBecomesTheEnum)
{
    Colour colour = Colour::Red;
    cli::CommandLine cli("paint", "Usage: aurorawall paint\n");
    cli.addChoice("colour", &colour, kColours, "the colour");
    Args args({"paint", "--colour", "green"});
    ASSERT_TRUE(cli.parse(args.argc(), args.argv()));
    EXPECT_EQ(colour, Colour::Green);
    EXPECT_TRUE(cli.given("colour"));
    EXPECT_NE(cli.help().find("--colour red|green"), std::string::npos) << cli.help();
}

TEST(CommandLine, DefaultChoiceIsNotGiven)
{
    Colour colour = Colour::Green;
    cli::CommandLine cli("paint", "Usage: aurorawall paint\n");
    cli.addChoice("colour", &colour, kColours, "the colour");
    Args args({"paint"});
    ASSERT_TRUE(cli.parse(args.argc(), args.argv()));
    EXPECT_EQ(colour, Colour::Green);
    EXPECT_FALSE(cli.given("colour"));
}

TEST(CommandLine, UnknownWordNamesTheOptionAndTheAllowedWords)
{
    Colour colour = Colour::Red;
    cli::CommandLine cli("paint", "Usage: aurorawall paint\n");
    cli.addChoice("colour", &colour, kColours, "the colour");
    Args args({"paint", "--colour", "blue"});
    try {
        cli.parse(args.argc(), args.argv());
        FAIL() << "no error for --colour blue";
    } catch (const common::UsageError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("--colour"), std::string::npos) << what;
        EXPECT_NE(what.find("'blue'"), std::string::npos) << what;
        EXPECT_NE(what.find("red, green"), std::string::npos) << what;
        EXPECT_NE(what.find("(see aurorawall paint --help)"), std::string::npos) << what;
    }
}

TEST(CommandLine, HelpStopsBeforeRequiredOptions)
{
    int count = 0;
    cli::CommandLine cli("paint", "Usage: aurorawall paint --count N\n");
    cli.add()("count", cli::po::value(&count)->required(), "how many");
    Args help({"paint", "--help"});
    EXPECT_FALSE(cli.parse(help.argc(), help.argv()));
    EXPECT_NE(cli.help().find("Usage: aurorawall paint"), std::string::npos);
    EXPECT_NE(cli.help().find("--count"), std::string::npos);
    cli::CommandLine missing("paint", "Usage: aurorawall paint --count N\n");
    missing.add()("count", cli::po::value(&count)->required(), "how many");
    Args none({"paint"});
    EXPECT_THROW(missing.parse(none.argc(), none.argv()), common::UsageError);
}

TEST(ExitStatus, UsageErrorIsTwoEverythingElseOne)
{
    EXPECT_EQ(cli::exitStatusOf(common::UsageError("--x")), 2);
    EXPECT_EQ(cli::exitStatusOf(common::InputError("wall.ini:3: bad")), 1);
    EXPECT_EQ(cli::exitStatusOf(std::runtime_error("no context")), 1);
    std::ostringstream out, err;
    EXPECT_EQ(cli::runCommand("paint", out, err, [] { throw common::UsageError("--x is bad"); }), 2);
    EXPECT_EQ(err.str(), "aurorawall paint: --x is bad\n");
    EXPECT_EQ(cli::runCommand("paint", out, err, [] {}), 0);
}

TEST(ExitStatus, OutputThatCannotBeWrittenIsARuntimeFailure)
{
    std::ostringstream out, err;
    out.setstate(std::ios::badbit);
    EXPECT_EQ(cli::runCommand("paint", out, err, [&] { out << "x"; }), 1);
    EXPECT_EQ(lines(err.str()).size(), 1u);
}

// ---- render's options ----

RenderOptions parseRender(std::vector<std::string> words)
{
    words.insert(words.begin(), "render");
    Args args(std::move(words));
    return parseRenderOptions(args.argc(), args.argv());
}

TEST(RenderOptions, EnumOptionsAreParsedOnce)
{
    const RenderOptions defaults = parseRender({"--wall", "w.ini", "--scene", "s.toml"});
    EXPECT_EQ(defaults.backend, gl::Backend::Egl);
    EXPECT_EQ(defaults.toneMap, io::ToneMap::Curve::AcesFilmic);
    EXPECT_EQ(defaults.balance, Balance::Auto);
    EXPECT_EQ(defaults.balanceBy, cluster::BandMeasure::Time);
    const RenderOptions o = parseRender({"--wall", "w.ini", "--scene", "s.toml", "--backend", "osmesa", "--tonemap",
                                         "magnitude-gamma", "--balance", "off", "--balance-by", "work"});
    EXPECT_EQ(o.backend, gl::Backend::Osmesa);
    EXPECT_EQ(o.toneMap, io::ToneMap::Curve::MagnitudeGamma);
    EXPECT_EQ(o.balance, Balance::Off);
    EXPECT_EQ(o.balanceBy, cluster::BandMeasure::Work);
    EXPECT_EQ(parseRender({"--wall", "w.ini", "--scene", "s.toml", "--balance"}).balance, Balance::On);
}

TEST(RenderOptions, WatchdogAndMovie)
{
    const RenderOptions defaults = parseRender({"--wall", "w.ini", "--scene", "s.toml"});
    EXPECT_EQ(defaults.rankTimeoutS, 10.0);
    EXPECT_TRUE(defaults.movieDir.empty());
    const RenderOptions o = parseRender(
        {"--wall", "w.ini", "--scene", "s.toml", "--rank-timeout", "2.5", "--movie", "m", "--movie-exr"});
    EXPECT_EQ(o.rankTimeoutS, 2.5);
    EXPECT_EQ(o.movieDir, "m");
    EXPECT_TRUE(o.movieExr);
}

TEST(RenderOptions, MistakesAreUsageErrorsNamingTheOption)
{
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
        {{"--backend", "vulkan"}, "--backend: unknown value 'vulkan' (allowed: egl, osmesa, glfw)"},
        {{"--tonemap", "reinhard"}, "(allowed: aces, magnitude-gamma)"},
        {{"--balance", "maybe"}, "(allowed: on, off, auto)"},
        {{"--balance-by", "pixels"}, "(allowed: time, work)"},
        {{"--bogus"}, "unrecognised option '--bogus'"},
        {{"--frames", "0"}, "--frames 0"},
        {{"--balance-bands", "0"}, "--balance-bands"},
        {{"--rank-timeout", "0"}, "--rank-timeout must be a number of seconds in [0.1, 1e6]"},
        {{"--rank-timeout", "nan"}, "--rank-timeout must be"},
        {{"--movie-exr"}, "--movie-exr needs --movie"},
    };
    for (const auto& [extra, expected] : cases) {
        std::vector<std::string> words = {"--wall", "w.ini", "--scene", "s.toml"};
        words.insert(words.end(), extra.begin(), extra.end());
        try {
            parseRender(words);
            ADD_FAILURE() << "no error for " << extra.front();
        } catch (const common::UsageError& e) {
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
        }
    }
}

// ---- tables ----

using Result = test::CommandOutput;

Result runTables(std::vector<std::string> options)
{
    return test::runInProcess(runTablesCommand, "tables", std::move(options));
}

TEST(TablesCommand, PrintsTheDepositionProfile)
{
    Result r = runTables({"deposition", "--energy-kev", "5"});
    ASSERT_EQ(r.status, 0) << r.err;
    std::vector<std::string> rows = lines(r.out);
    ASSERT_EQ(rows.size(), 1082u);
    EXPECT_EQ(rows[0], "altitude_km,rate");
    EXPECT_EQ(rows[1].substr(0, 5), "60.0,");
    EXPECT_EQ(rows.back().substr(0, 6), "600.0,");
    // 112.5 km is row 1 + 105.
    double rate = std::stod(rows[106].substr(rows[106].find(',') + 1));
    EXPECT_NEAR(rate / components::aurora::physics::depositionRate(112.5, 5.0, components::aurora::physics::Spectrum::Monoenergetic), 1.0, 1e-9);
}

TEST(TablesCommand, MaxwellianFlagSelectsTheSpectrum)
{
    Result r = runTables({"deposition", "--energy-kev", "2", "--maxwellian"});
    ASSERT_EQ(r.status, 0) << r.err;
    std::vector<std::string> rows = lines(r.out);
    double rate = std::stod(rows[101].substr(rows[101].find(',') + 1)); // 110 km
    EXPECT_NEAR(rate / components::aurora::physics::depositionRate(110.0, 2.0, components::aurora::physics::Spectrum::Maxwellian), 1.0, 1e-9);
}

TEST(TablesCommand, BadOptionsNameTheOptionAndExit2)
{
    const std::vector<std::vector<std::string>> bad = {
        {"deposition"}, {"deposition", "--energy-kev", "abc"}, {"deposition", "--energy-kev", "-1"},
        {"deposition", "--energy-kev", "5", "--bogus"}, {"ozone", "--energy-kev", "5"}, {"--energy-kev", "5"}};
    const std::vector<std::string> named = {"energy-kev", "energy-kev", "energy-kev", "bogus", "ozone", "table"};
    for (size_t i = 0; i < bad.size(); ++i) {
        Result r = runTables(bad[i]);
        EXPECT_EQ(r.status, 2) << i;
        EXPECT_TRUE(r.out.empty()) << i;
        EXPECT_NE(r.err.find(named[i]), std::string::npos) << r.err;
        EXPECT_EQ(r.err.rfind("aurorawall tables: ", 0), 0u) << r.err;
        EXPECT_EQ(lines(r.err).size(), 1u) << r.err;
    }
}

// ---- airmass ----

int runAirmass(std::vector<std::string> args, const std::string& input, std::string& out, std::string& err)
{
    std::istringstream in(input);
    const Result r = test::runInProcess(
        [&](int argc, char** argv, std::ostream& o, std::ostream& e) { return runAirmassCommand(argc, argv, in, o, e); },
        std::move(args));
    out = r.out;
    err = r.err;
    return r.status;
}

TEST(AirmassCommand, ListsMethodsAndComputes)
{
    std::string out, err;
    ASSERT_EQ(runAirmass({"airmass", "--method", "list"}, "", out, err), 0);
    EXPECT_NE(out.find("exact\n"), std::string::npos);
    EXPECT_NE(out.find(std::string(aurorawall::physics::atmosphere::kDefaultAirmassMethod) + "\n"), std::string::npos);
    std::string input = "ox,oy,oz,dx,dy,dz,t0,t1,H,R\n\n0,6371,0,0,1,0,0,100,8,6371\n0,6371,0,0,1,0,100,0,8,6371\n";
    ASSERT_EQ(runAirmass({"airmass", "--method", "exact"}, input, out, err), 0);
    double expected = 8.0 * (1.0 - std::exp(-100.0 / 8.0));
    std::istringstream lines(out);
    double first = 0.0, second = 0.0;
    lines >> first >> second;
    EXPECT_NEAR(first, expected, 1e-9);
    EXPECT_NEAR(second, -expected, 1e-9);
    ASSERT_EQ(runAirmass({"airmass"}, input, out, err), 0); // the default, float32
    std::istringstream defaultLines(out);
    defaultLines >> first;
    EXPECT_NEAR(first, expected, 1e-5 * expected);
    ASSERT_EQ(runAirmass({"airmass", "--help"}, "", out, err), 0);
    EXPECT_NE(out.find("--method"), std::string::npos);
}

TEST(AirmassCommand, MalformedLinesAreARuntimeFailureNamingTheLine)
{
    for (const std::string& bad : {std::string("1,2,3\n"), std::string("0,6371,0,0,1,0,0,x,8,6371\n"),
                                   std::string("0,6371,0,0,1,0,0,nan,8,6371\n"), std::string("0,6371,0,0,1,0,0,inf,8,6371\n"),
                                   std::string("0,6371,0,0,1,0,0,1,0,6371\n"), std::string("0,6371,0,0,1,0,0,1,8,-1\n"),
                                   std::string("0,6371,0,0,1,0,0,1,8,6371,\n")}) {
        std::string out, err;
        EXPECT_EQ(runAirmass({"airmass"}, "0,6371,0,0,1,0,0,100,8,6371\n\n" + bad, out, err), 1) << bad;
        EXPECT_EQ(out, "") << bad;
        EXPECT_NE(err.find("line 3"), std::string::npos) << err;
    }
    std::string out, err;
    EXPECT_EQ(runAirmass({"airmass", "--method", "nope"}, "", out, err), 2);
    EXPECT_NE(err.find("--method"), std::string::npos) << err;
    EXPECT_NE(err.find(aurorawall::physics::atmosphere::kDefaultAirmassMethod), std::string::npos) << err; // the allowed words
}


// The header is a first line of the column names (any case, spaces around them); any other first
// line is data, and "nan,..." or other names an error.
TEST(AirmassCommand, HeaderIsALineOfTheColumnNames)
{
    const std::string ray = "0,6371,0,0,1,0,0,100,8,6371\n";
    std::string out, err;
    for (const std::string header : {"ox,oy,oz,dx,dy,dz,t0,t1,H,R", " OX, oy ,oz,dx,dy,dz,t0,t1,h,r "}) {
        EXPECT_EQ(runAirmass({"airmass"}, header + "\n" + ray, out, err), 0) << err;
        EXPECT_EQ(lines(out).size(), 1u) << header;
    }
    for (const std::string first : {"nan,0,0,0,0,0,0,0,1,1", "inf,0,6371,0,1,0,0,100,8,6371", "x,y,z,dx,dy,dz,t0,t1,H,R"}) {
        EXPECT_EQ(runAirmass({"airmass"}, first + "\n" + ray, out, err), 1) << first;
        EXPECT_EQ(out, "");
        EXPECT_NE(err.find("line 1: field 1 (ox) is not"), std::string::npos) << err;
    }
    EXPECT_EQ(runAirmass({"airmass"}, ray + "ox,oy,oz,dx,dy,dz,t0,t1,H,R\n", out, err), 1); // a header only comes first
    EXPECT_NE(err.find("line 2: field 1 (ox) is not a number: 'ox'"), std::string::npos) << err;
}

// Every field must be a float (the closed forms run in float32): 1e308 became inf and the result NaN,
// an H of 1e-320 became 0. A ray the method gives no finite value for is an error naming the line and
// the method, never a NaN printed with status 0.
TEST(AirmassCommand, FieldsBeyondFloatAndNonFiniteResultsAreErrors)
{
    const std::vector<std::pair<std::string, std::string>> bad = {
        {"1e308,0,0,1,0,0,0,100,8,6371", "line 1: field 1 (ox) must be within float's range"},
        {"0,6371,0,0,-3.5e38,0,0,100,8,6371", "line 1: field 5 (dy) must be within float's range"},
        {"0,6371,0,0,1,0,0,100,1e-320,6371", "line 1: field 9 (H) must be at least 1.4012985e-45 km"},
        {"0,6371,0,0,1,0,0,100,1.4e-45,6371", "line 1: field 9 (H) must be at least 1.4012985e-45 km"},
        {"0,6371,0,0,1,0,0,100,8,1e39", "line 1: field 10 (R) must be within float's range"},
        // Only decimal numbers: strtod alone would take these, or stop quietly at the NUL.
        {"0x10,6371,0,0,1,0,0,100,8,6371", "line 1: field 1 (ox) is not a number: '0x10'"},
        {"0,6371,0,0,1,0,0,100,8,inf", "line 1: field 10 (R) is not a number: 'inf'"},
        {std::string("0,6371\0junk,0,0,1,0,0,100,8,6371", 32), "line 1: field 2 (oy) is not a number"},
        {"0,6371,0,0,1,0,0,100,8,1e", "line 1: field 10 (R) is not a number: '1e'"},
        {"0,6371,0,0,1,.,0,100,8,6371", "line 1: field 6 (dz) is not a number: '.'"},
    };
    std::string out, err;
    for (const auto& [line, expected] : bad) {
        EXPECT_EQ(runAirmass({"airmass", "--method", "exact"}, line + "\n", out, err), 1) << line;
        EXPECT_EQ(out, "");
        EXPECT_NE(err.find(expected), std::string::npos) << err;
    }
    const std::string fromTheCentre = "0,6371,0,1,0.2,0,0,100,8,6371\n0,0,0,1,0,0,0,100,8,6371\n";
    EXPECT_EQ(runAirmass({"airmass", "--method", "lawlor-winitzki"}, fromTheCentre, out, err), 1);
    EXPECT_EQ(out, "");
    EXPECT_NE(err.find("line 2: lawlor-winitzki gives no finite airmass for this ray"), std::string::npos) << err;
    for (const char* method : {aurorawall::physics::atmosphere::kDefaultAirmassMethod, "exact", "lawlor-erfcx", "march16"}) {
        EXPECT_EQ(runAirmass({"airmass", "--method", method}, fromTheCentre, out, err), 0) << method << err;
        EXPECT_EQ(lines(out).size(), 2u);
    }
    EXPECT_EQ(runAirmass({"airmass"}, "3.4028234e38,0,0,1,0,0,0,100,1.5e-45,6371\n", out, err), 0) << err;
    // The bound the messages print (float's smallest positive number rounded up) is itself accepted.
    EXPECT_EQ(runAirmass({"airmass"}, "0,0,7000,1,0,0,0,100,1.4012985e-45,6371\n", out, err), 0) << err;
    EXPECT_EQ(runAirmass({"airmass"}, "+1.,-.5,0,1E0,0,0,0,1e+2,8.,6371\n", out, err), 0) << err;
}

// ---- accuracy, up to its first GL call ----

Result runAccuracy(std::vector<std::string> options)
{
    return test::runInProcess(runAccuracyCommand, "accuracy", std::move(options));
}

TEST(AccuracyCommand, OneParserForTheThreeKinds)
{
    const std::vector<std::pair<std::vector<std::string>, std::string>> usage = {
        {{}, "choose --airmass, --sky, --scene FILE or --glory FILE"},
        {{"--scene", "s.toml", "--airmass"}, "--scene cannot be combined"},
        {{"--scene", "s.toml", "--repeat", "4"}, "--repeat applies to --airmass and --sky only"},
        {{"--sky", "--size", "10x10"}, "--size applies to --scene only"},
        {{"--scene", "s.toml", "--size", "10by10"}, "--size"},
        {{"--airmass", "--repeat", "0"}, "--repeat"},
        {{"--bogus"}, "unrecognised option '--bogus'"},
        {{"--glory", "s.toml", "--scene", "s.toml"}, "--glory cannot be combined with --scene"},
        {{"--glory", "s.toml", "--pixels", "9"}, "--pixels applies to --scene only"},
        {{"--glory", "s.toml", "--airmass"}, "--glory cannot be combined with --airmass"},
        // inf was taken, and printed as the reference's step; 1e-300 would never end.
        {{"--scene", "s.toml", "--reference-step-km", "inf"}, "--reference-step-km must be in [0.001, 0.25] km (got inf)"},
        {{"--scene", "s.toml", "--reference-step-km", "1e-300"}, "--reference-step-km must be in [0.001, 0.25] km (got 1e-300)"},
        {{"--scene", "s.toml", "--reference-step-km", "0.2500001"}, "--reference-step-km"},
        {{"--scene", "s.toml", "--reference-step-km", "-0"}, "--reference-step-km"},
        {{"--scene", "s.toml", "--views", "0"}, "--views must be a whole number in [1, 10000] (got 0)"},
        {{"--scene", "s.toml", "--views", "10001"}, "--views must be a whole number in [1, 10000]"},
        {{"--scene", "s.toml", "--views", "two"}, "--views"},
        {{"--scene", "s.toml", "--seed", "3"}, "--seed applies to --views only"},
        {{"--scene", "s.toml", "--views", "4", "--work-stats"}, "choose at most one of --feature-costs, --work-stats and --views"},
        {{"--glory", "s.toml", "--views", "4"}, "--views applies to --scene only"},
    };
    for (const auto& [words, expected] : usage) {
        const Result r = runAccuracy(words);
        EXPECT_EQ(r.status, 2) << expected;
        EXPECT_EQ(lines(r.err).size(), 1u) << r.err;
        EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
        EXPECT_TRUE(r.out.empty()) << r.out;
    }
    const Result help = runAccuracy({"--help"});
    EXPECT_EQ(help.status, 0);
    for (const char* option : {"--airmass", "--sky", "--scene", "--repeat", "--feature-costs", "--views", "--seed"})
        EXPECT_NE(help.out.find(option), std::string::npos) << option;
}

TEST(AccuracyCommand, UnreadableSceneIsARuntimeFailure)
{
    const Result r = runAccuracy({"--scene", "/nonexistent/scene.toml"});
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("/nonexistent/scene.toml"), std::string::npos) << r.err;
    EXPECT_EQ(lines(r.err).size(), 1u) << r.err;
}

// ---- what error messages echo of the input ----

TEST(EchoedInput, LongTextIsCutWithItsLengthAndControlCharactersEscaped)
{
    EXPECT_EQ(common::echoedInput("1.5e3"), "1.5e3");
    EXPECT_EQ(common::echoedInput(std::string(60, 'a')), std::string(60, 'a'));
    EXPECT_EQ(common::echoedInput(std::string(61, 'a')), std::string(60, 'a') + "… (61 bytes)");
    EXPECT_EQ(common::echoedInput("a\nb\tc\x01\x7f"), "a\\nb\\tc\\x01\\x7F");
    // A two-byte character across the limit is left out whole.
    EXPECT_EQ(common::echoedInput(std::string(59, 'a') + "\xc3\xa9" + "b"), std::string(59, 'a') + "… (62 bytes)");
}

// However long a value, the error that quotes it is one short line with the value's start and length.
TEST(EchoedInput, ErrorsQuotingAHugeValueStayOneShortLine)
{
    const std::string word(1 << 20, 'w');
    const std::string length = "(1048576 bytes)";
    const auto expectShort = [&](const std::string& error, const std::string& what) {
        EXPECT_EQ(lines(error).size(), 1u) << what;
        EXPECT_LT(error.size(), 400u) << what;
        EXPECT_NE(error.find(length), std::string::npos) << what << ": " << error.substr(0, 400);
    };
    std::string out, err;
    EXPECT_EQ(runAirmass({"airmass"}, "0,6371,0,0,1,0,0,100,8," + word + "\n", out, err), 1);
    expectShort(err, "airmass field");
    expectShort(runTables({word, "--energy-kev", "5"}).err, "tables TABLE");
    expectShort(runAccuracy({"--scene", "s.toml", "--size", word}).err, "accuracy --size");
    try {
        parseRender({"--wall", "w.toml", "--scene", "s.toml", "--backend", word});
        ADD_FAILURE() << "render --backend: no error";
    } catch (const common::UsageError& e) {
        expectShort(e.what(), "render --backend");
    }
    // The control server takes lines of up to 1024 bytes.
    for (const std::string& line : {std::string(1000, 'w'), "speed " + std::string(1000, '7')}) {
        try {
            control::parseCommand(line);
            ADD_FAILURE() << "control: no error";
        } catch (const control::CommandError& e) {
            EXPECT_LT(std::string(e.what()).size(), 400u) << e.what();
            EXPECT_NE(std::string(e.what()).find("(1000 bytes)"), std::string::npos) << e.what();
        }
    }
    const std::filesystem::path scene = std::filesystem::temp_directory_path() / "aurorawall-echo-test.toml";
    std::ofstream(scene) << "[scene]\nname = \"echo\"\ncomponents = [\"" << word << "\"]\n";
    try {
        components::loadScene(scene.string());
        ADD_FAILURE() << "scene: no error";
    } catch (const common::InputError& e) {
        expectShort(e.what(), "scene component");
    }
    std::filesystem::remove(scene);
}

// ---- render --cost-map: option, colour map and scale bar ----

TEST(RenderOptions, CostMapNeedsAPngAndTheStaticSplit)
{
    const RenderOptions o = parseRender({"--wall", "w.ini", "--scene", "s.toml", "--cost-map", "cost.png"});
    EXPECT_EQ(o.costMapFile, "cost.png");
    EXPECT_EQ(o.balance, Balance::Off);
    for (const auto& [extra, expected] : std::vector<std::pair<std::vector<std::string>, std::string>>{
             {{"--cost-map", "cost.exr"}, "--cost-map cost.exr: the file name must end in .png"},
             {{"--cost-map", "cost.png", "--balance"}, "--cost-map needs the static split"}}) {
        std::vector<std::string> words = {"--wall", "w.ini", "--scene", "s.toml"};
        words.insert(words.end(), extra.begin(), extra.end());
        EXPECT_THROW(
            try { parseRender(words); } catch (const common::UsageError& e) {
                EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
                throw;
            },
            common::UsageError);
    }
}

// The most 8-bit rounding may lower the luminance from one colour-map step to the next.
constexpr double kRoundingDip = 5e-4;

// Relative luminance Y of an 8-bit sRGB colour (IEC 61966-2-1 transfer function, Rec. 709 weights).
double luminance(Rgb8 c)
{
    auto linear = [](std::uint8_t v) {
        const double e = v / 255.0;
        return e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4);
    };
    return 0.2126 * linear(c[0]) + 0.7152 * linear(c[1]) + 0.0722 * linear(c[2]);
}

TEST(CostMap, ViridisRunsFromTheTablesFirstToItsLastEntry)
{
    // Matplotlib's viridis entries 0 and 255, times 255, rounded.
    EXPECT_EQ(viridis(0.0), (Rgb8{68, 1, 84}));
    EXPECT_EQ(viridis(1.0), (Rgb8{253, 231, 37}));
    EXPECT_EQ(viridis(-3.0), viridis(0.0));
    EXPECT_EQ(viridis(7.0), viridis(1.0));
    // Entry 128 is a table node: (0.127568, 0.566949, 0.550556).
    EXPECT_EQ(viridis(128.0 / 255.0), (Rgb8{33, 145, 140}));
}

TEST(CostMap, ViridisLuminanceIncreasesMonotonically)
{
    // Strictly increasing over steps of 1/32, and a wide range: Y runs from 0.013 to 0.77. Between
    // neighbouring 8-bit steps rounding can swap the order by less than one code of red and blue
    // (about 3.6e-4 in Y mid-range; the largest dip measured is 2.9e-4).
    for (int i = 1; i <= 255; ++i)
        EXPECT_LE(luminance(viridis((i - 1) / 255.0)), luminance(viridis(i / 255.0)) + kRoundingDip) << i;
    for (int i = 1; i <= 32; ++i)
        EXPECT_LT(luminance(viridis((i - 1) / 32.0)), luminance(viridis(i / 32.0))) << i;
    EXPECT_LT(luminance(viridis(0.0)), 0.02);
    EXPECT_GT(luminance(viridis(1.0)), 0.7);
}

TEST(CostMap, ScaleIsLogarithmicBetweenTheCheapestAndTheCostliestPixel)
{
    const CostScale scale{10.0, 1000.0};
    EXPECT_DOUBLE_EQ(scale.position(10.0), 0.0);
    EXPECT_DOUBLE_EQ(scale.position(1000.0), 1.0);
    EXPECT_NEAR(scale.position(100.0), 0.5, 1e-15);
    EXPECT_DOUBLE_EQ(scale.position(1.0), 0.0);
    EXPECT_DOUBLE_EQ(scale.position(1e6), 1.0);
    EXPECT_DOUBLE_EQ((CostScale{5.0, 5.0}).position(5.0), 0.0);
}

TEST(CostMap, PictureIsTheMapWithALabelledScaleBarBelow)
{
    const int width = 400, height = 10;
    std::vector<double> cost(width * height, 100.0);
    cost[0] = 10.0;   // cheapest: the colour map's first entry
    cost[1] = 1000.0; // costliest: its last
    cost[2] = 0.0;    // nothing drawn (a bezel): black
    const Picture p = costMapPicture(width, height, cost);
    ASSERT_EQ(p.width, width);
    ASSERT_EQ(p.height, height + scaleBarHeight(width));
    EXPECT_EQ(p.at(0, 0), viridis(0.0));
    EXPECT_EQ(p.at(1, 0), viridis(1.0));
    EXPECT_EQ(p.at(2, 0), (Rgb8{0, 0, 0}));
    EXPECT_EQ(p.at(3, 0), viridis(0.5));

    // The strip: a row of the bar whose colours run from the map's first to its last entry with
    // luminance increasing (up to 8-bit rounding).
    int stripRow = -1;
    for (int y = height; y < p.height && stripRow < 0; ++y)
        for (int x = 0; x < width; ++x)
            if (p.at(x, y) == viridis(0.0)) {
                stripRow = y;
                break;
            }
    ASSERT_GE(stripRow, height);
    int first = 0, last = width - 1;
    while (p.at(first, stripRow) != viridis(0.0)) ++first;
    while (p.at(last, stripRow) != viridis(1.0)) --last;
    EXPECT_GT(last - first, width * 9 / 10);
    for (int x = first + 1; x <= last; ++x)
        EXPECT_LE(luminance(p.at(x - 1, stripRow)), luminance(p.at(x, stripRow)) + kRoundingDip) << x;

    // Labels: white text below the strip at both ends and the middle of the strip ("10.0", "100",
    // "1000"), and the caption on the last text line.
    auto whiteIn = [&](int x0, int x1, int y0, int y1) {
        int n = 0;
        for (int y = y0; y < y1; ++y)
            for (int x = std::max(0, x0); x < std::min(width, x1); ++x)
                n += p.at(x, y) == Rgb8{255, 255, 255};
        return n;
    };
    const int stripEnd = [&] {
        int y = stripRow;
        while (p.at(first, y) == viridis(0.0)) ++y;
        return y;
    }();
    const int labelRows = (p.height - stripEnd) / 2;
    EXPECT_GT(whiteIn(first, first + 30, stripEnd + 3, stripEnd + labelRows), 10);
    EXPECT_GT(whiteIn((first + last) / 2 - 15, (first + last) / 2 + 15, stripEnd + 3, stripEnd + labelRows), 10);
    EXPECT_GT(whiteIn(last - 30, last + 1, stripEnd + 3, stripEnd + labelRows), 10);
    EXPECT_GT(whiteIn(first, first + 6 * 21, stripEnd + labelRows, p.height), 100); // "ns per pixel estimate"
    EXPECT_EQ(whiteIn(first + 6 * 21 + 1, width, stripEnd + labelRows, p.height), 0);
}

TEST(AccuracyCommand, FrameIsAWholeNumberForScenesOnly)
{
    for (const auto& [words, expected] : std::vector<std::pair<std::vector<std::string>, std::string>>{
             {{"--scene", "s.toml", "--frame", "-1"}, "--frame must be a whole number in [0, 1e8] (got -1)"},
             {{"--scene", "s.toml", "--frame", "2.5"}, "--frame"},
             {{"--airmass", "--frame", "3"}, "--frame applies to --scene only"}}) {
        const Result r = runAccuracy(words);
        EXPECT_EQ(r.status, 2) << expected;
        EXPECT_EQ(lines(r.err).size(), 1u) << r.err;
        EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
    }
    EXPECT_NE(runAccuracy({"--help"}).out.find("--frame"), std::string::npos);
}

} // namespace
} // namespace aurorawall::app

namespace aurorawall::app {
namespace {

// A frame's state with a camera turned by `angle` about the planet's z axis and tilted, 6400 km out.
cluster::FrameState recordedFrame(std::uint64_t frame, double timeS, double angle)
{
    cluster::FrameState s;
    s.frame = frame;
    s.timeS = timeS;
    s.cameraPositionKm = glm::dvec3(6400.0 * std::cos(angle), 6400.0 * std::sin(angle), 123.456789 * angle);
    const glm::dvec3 forward = glm::normalize(glm::dvec3(-std::sin(angle), std::cos(angle), 0.3 + angle));
    const glm::dvec3 up0 = glm::dvec3(0.2 * std::cos(angle), 0.2 * std::sin(angle), 1.0);
    s.cameraBack = -forward;
    s.cameraUp = glm::normalize(up0 - forward * glm::dot(up0, forward));
    s.cameraRight = glm::cross(forward, s.cameraUp);
    return s;
}

std::string recordFile(const std::string& name)
{
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "aurorawall-record-test";
    std::filesystem::create_directories(folder);
    return (folder / name).string();
}

// The recorded scene, read back by the scene reader and played by the master clock with the
// recorded start time and step, gives the recorded camera at every frame: the keys hold 17
// significant digits (exact doubles), the path is exact at its keys, and the camera's vectors go
// through a quaternion (orientationOf/frameOf), a rounding of about 1e-16 each.
TEST(PathRecorder, RecordedSceneReplaysTheCameraOfEveryFrame)
{
    const std::string file = recordFile("flight.toml");
    PathRecorder recorder(file, AW_SCENES_DIR "/substorm.toml", 180.0, 0.5);
    std::vector<cluster::FrameState> frames;
    for (std::uint64_t f = 0; f < 7; ++f) {
        frames.push_back(recordedFrame(f, 180.0 + f * 0.5, 0.37 * f * f)); // turning faster and faster
        recorder.add(frames.back());
    }
    recorder.write();

    const scene::Scene replayed = components::loadScene(file);
    EXPECT_EQ(replayed.startTimeS, 180.0);
    EXPECT_EQ(replayed.timeStepS, 0.5);
    ASSERT_EQ(replayed.camera.path.keys().size(), frames.size());
    cluster::ClockSettings settings;
    settings.frames = frames.size();
    settings.startTimeS = replayed.startTimeS;
    settings.timeStepS = replayed.timeStepS;
    cluster::MasterClock clock(settings, replayed.camera, 1.0);
    for (const cluster::FrameState& recorded : frames) {
        const cluster::FrameState played = clock.next(false);
        EXPECT_EQ(played.timeS, recorded.timeS);
        for (int i = 0; i < 3; ++i) {
            EXPECT_NEAR(played.cameraPositionKm[i], recorded.cameraPositionKm[i], 1e-12) << "frame " << recorded.frame;
            EXPECT_NEAR(played.cameraBack[i], recorded.cameraBack[i], 1e-12) << "frame " << recorded.frame;
            EXPECT_NEAR(played.cameraUp[i], recorded.cameraUp[i], 1e-12) << "frame " << recorded.frame;
        }
    }
    // Between keys the path interpolates: half a step after the second key the camera has moved on.
    const glm::dvec3 between = replayed.camera.path.positionAt(180.75);
    EXPECT_GT(glm::length(between - frames[1].cameraPositionKm), 1.0);
}

// Keys need increasing times: a paused frame replaces the last key, a clock set back drops the keys
// from its time on; one camera is written as a still [camera], which the reader accepts.
TEST(PathRecorder, KeepsTheFlightLastFlownThroughEachTime)
{
    const std::string file = recordFile("paused.toml");
    PathRecorder recorder(file, AW_SCENES_DIR "/substorm.toml", 0.0, 1.0);
    recorder.add(recordedFrame(0, 0.0, 0.0));
    recorder.add(recordedFrame(1, 1.0, 0.1));
    recorder.add(recordedFrame(2, 2.0, 0.2));
    recorder.add(recordedFrame(3, 2.0, 0.3)); // paused, then moved: replaces the key at 2 s
    ASSERT_EQ(recorder.cameras().size(), 3u);
    EXPECT_EQ(recorder.cameras().back().positionKm, recordedFrame(3, 2.0, 0.3).cameraPositionKm);
    recorder.add(recordedFrame(4, 1.0, 0.4)); // set back to 1 s: the keys at 1 s and 2 s go
    ASSERT_EQ(recorder.cameras().size(), 2u);
    EXPECT_EQ(recorder.cameras().back().positionKm, recordedFrame(4, 1.0, 0.4).cameraPositionKm);

    PathRecorder still(file, AW_SCENES_DIR "/substorm.toml", 5.0, 1.0);
    still.add(recordedFrame(0, 5.0, 0.7));
    still.write();
    const scene::Scene s = components::loadScene(file);
    EXPECT_TRUE(s.camera.path.empty());
    EXPECT_EQ(s.camera.speedKmPerS, 0.0);
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(s.camera.positionKm[i], recordedFrame(0, 5.0, 0.7).cameraPositionKm[i]);
        EXPECT_NEAR(s.camera.forward[i], -recordedFrame(0, 5.0, 0.7).cameraBack[i], 1e-15);
    }
}

// A plain [camera] has no zoom, so one zoomed frame is kept as two keys that hold it.
TEST(PathRecorder, OneZoomedFrameReplaysItsZoom)
{
    for (double step : {0.5, 0.0}) {
        const std::string file = recordFile("zoomed.toml");
        PathRecorder recorder(file, AW_SCENES_DIR "/substorm.toml", 5.0, step);
        cluster::FrameState zoomed = recordedFrame(0, 5.0, 0.7);
        zoomed.zoom = 2.75;
        recorder.add(zoomed);
        recorder.write();
        const scene::Scene s = components::loadScene(file);
        ASSERT_EQ(s.camera.path.keys().size(), 2u) << "step " << step;
        cluster::ClockSettings settings;
        settings.frames = 1;
        settings.startTimeS = s.startTimeS;
        settings.timeStepS = s.timeStepS;
        cluster::MasterClock clock(settings, s.camera, 1.0);
        const cluster::FrameState played = clock.next(false);
        EXPECT_EQ(played.timeS, 5.0);
        EXPECT_NEAR(played.zoom, 2.75, 1e-12) << "step " << step;
        for (int i = 0; i < 3; ++i) {
            EXPECT_NEAR(played.cameraPositionKm[i], zoomed.cameraPositionKm[i], 1e-12);
            EXPECT_NEAR(played.cameraBack[i], zoomed.cameraBack[i], 1e-12);
        }
    }
}

} // namespace
} // namespace aurorawall::app
