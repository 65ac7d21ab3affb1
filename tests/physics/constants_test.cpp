// Each constant is written once in C++ (src/physics/constants.h) and, where the shaders need it, once
// in GLSL (shaders/physics/constants.glsl): no other source, shader or test spells it out.
#include "physics/constants.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace aurorawall::physics {
namespace {

const std::filesystem::path kSource = AURORAWALL_SOURCE_DIR;
const std::filesystem::path kCppDefinitions = kSource / "src/physics/constants.h";
const std::filesystem::path kGlslDefinitions = kSource / "shaders/physics/constants.glsl";

std::string contents(const std::filesystem::path& file)
{
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// The text without its // and /* */ comments (prose may quote a value: "683 lm/W"), each replaced by a
// space. A scan, not a regex: libstdc++'s regex executor recurses once a character, and a long comment
// overflows the stack.
std::string code(const std::string& text)
{
    std::string result;
    result.reserve(text.size());
    for (size_t i = 0; i < text.size();) {
        if (text.compare(i, 2, "//") == 0) {
            i = std::min(text.find('\n', i), text.size());
            result += ' ';
        } else if (text.compare(i, 2, "/*") == 0) {
            const size_t end = text.find("*/", i + 2);
            i = end == std::string::npos ? text.size() : end + 2;
            result += ' ';
        } else
            result += text[i++];
    }
    return result;
}

struct Scan {
    size_t files = 0;
    std::vector<std::string> offenders; // "path: count"
};

// Counts the matches of `pattern` in every C++ and GLSL source under src/, shaders/ and tests/ (this
// test aside); each file of `definitions` must match exactly once, every other file never.
Scan scan(const std::regex& pattern, const std::vector<std::filesystem::path>& definitions, bool withComments)
{
    Scan result;
    for (const char* folder : {"src", "shaders", "tests"})
        for (const auto& entry : std::filesystem::recursive_directory_iterator(kSource / folder)) {
            const std::string extension = entry.path().extension().string();
            if (!entry.is_regular_file() || (extension != ".cpp" && extension != ".h" && extension != ".glsl" &&
                                             extension != ".comp" && extension != ".frag" && extension != ".in"))
                continue;
            if (entry.path().filename() == "constants_test.cpp")
                continue;
            ++result.files;
            const std::string raw = contents(entry.path());
            const std::string text = withComments ? raw : code(raw);
            const auto found = std::distance(std::sregex_iterator(text.begin(), text.end(), pattern), std::sregex_iterator());
            bool definition = false;
            for (const auto& d : definitions)
                definition = definition || entry.path() == d;
            if (found != (definition ? 1 : 0))
                result.offenders.push_back(std::filesystem::relative(entry.path(), kSource).string() + ": " +
                                           std::to_string(found));
        }
    return result;
}

std::string list(const std::vector<std::string>& offenders)
{
    std::string text;
    for (const std::string& o : offenders)
        text += o + "; ";
    return text;
}

TEST(Constants, CommentsAreLeftOutOfTheCode)
{
    EXPECT_EQ(code("a // 683 lm/W\nb /* 683\n 683 */ c"), "a  \nb   c");
    EXPECT_EQ(code("x /* 1 / 2 **/ y // end"), "x   y  ");
    EXPECT_EQ(code("open /* never closed"), "open  ");
    EXPECT_EQ(code(std::string(1 << 20, '*').insert(0, "/*") + "*/z"), " z"); // a megabyte of comment
}

TEST(Constants, PiIsDefinedOnceInCppAndOnceInGlsl)
{
    // π's digits, M_PI, or π computed from a trigonometric function, comments included.
    const std::regex pi(R"(3\.14159|\bM_PI\b|acos\(\s*-1|atan\(\s*1(\.0*)?\s*\)\s*\*\s*4)");
    const Scan result = scan(pi, {kCppDefinitions, kGlslDefinitions}, true);
    EXPECT_GT(result.files, 100u);
    EXPECT_TRUE(result.offenders.empty()) << "π spelt out (count) in: " << list(result.offenders);
}

// The physical constants, by the leading digits of their values (in code; prose may quote them).
TEST(Constants, PhysicalConstantsAreDefinedOnceInCpp)
{
    const std::vector<std::pair<const char*, std::regex>> constants = {
        {"h", std::regex(R"(6\.626070)")},
        {"c", std::regex(R"(2\.99792458|299792458|2\.998e8)")},
        {"k", std::regex(R"(1\.380649)")},
        {"e", std::regex(R"(1\.602176)")},
        {"m_e", std::regex(R"(9\.109383)")},
        {"epsilon_0", std::regex(R"(8\.854187)")},
        {"683 lm/W", std::regex(R"((^|[^\w.])683(\.0*)?([^\w.]|$))")},
    };
    for (const auto& [name, pattern] : constants) {
        const Scan result = scan(pattern, {kCppDefinitions}, false);
        EXPECT_GT(result.files, 100u);
        EXPECT_TRUE(result.offenders.empty()) << name << " spelt out (count) in: " << list(result.offenders);
    }
}

// Constants derived from others are computed from them, never spelt out: keV per erg is 1e-10/e
// (its leading digits, in code).
TEST(Constants, DerivedConstantsAreComputed)
{
    const Scan result = scan(std::regex(R"(6\.241509)"), {}, false);
    EXPECT_GT(result.files, 100u);
    EXPECT_TRUE(result.offenders.empty()) << "keV per erg spelt out (count) in: " << list(result.offenders);
}

TEST(Constants, Values)
{
    EXPECT_DOUBLE_EQ(kDegree * 180.0, kPi);
    EXPECT_NEAR(kPlanck * kSpeedOfLight, 1.98644586e-25, 1e-33); // J m
    EXPECT_EQ(kLumensPerWatt, 683.0);
    EXPECT_DOUBLE_EQ(kKeVPerErg * 1e10 * kElementaryCharge, 1.0);
}

} // namespace
} // namespace aurorawall::physics
