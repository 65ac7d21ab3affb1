// Each mathematical constant is written once in C++ (src/common/constants.h) and once in GLSL
// (shaders/physics/constants.glsl): no other source, shader or test spells out π.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

const std::filesystem::path kSource = AURORAWALL_SOURCE_DIR;

std::string contents(const std::filesystem::path& file)
{
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

} // namespace

TEST(Constants, PiIsDefinedOnceInCppAndOnceInGlsl)
{
    // π's digits, M_PI, or π computed from a trigonometric function.
    const std::regex pi(R"(3\.14159|\bM_PI\b|acos\(\s*-1|atan\(\s*1(\.0*)?\s*\)\s*\*\s*4)");
    const std::vector<std::filesystem::path> definitions = {kSource / "src/common/constants.h",
                                                            kSource / "shaders/physics/constants.glsl"};
    std::vector<std::string> offenders;
    size_t scanned = 0;
    for (const char* folder : {"src", "shaders", "tests"})
        for (const auto& entry : std::filesystem::recursive_directory_iterator(kSource / folder)) {
            const std::string extension = entry.path().extension().string();
            if (!entry.is_regular_file() || (extension != ".cpp" && extension != ".h" && extension != ".glsl" &&
                                             extension != ".comp" && extension != ".frag" && extension != ".in"))
                continue;
            ++scanned;
            const std::string text = contents(entry.path());
            const auto found = std::distance(std::sregex_iterator(text.begin(), text.end(), pi), std::sregex_iterator());
            const bool definition = entry.path() == definitions[0] || entry.path() == definitions[1];
            if (found != (definition ? 1 : 0) && entry.path().filename() != "constants_test.cpp")
                offenders.push_back(std::filesystem::relative(entry.path(), kSource).string() + ": " +
                                    std::to_string(found));
        }
    EXPECT_GT(scanned, 100u);
    EXPECT_TRUE(offenders.empty()) << "π spelt out (count) in: " << [&] {
        std::string list;
        for (const std::string& o : offenders)
            list += o + "; ";
        return list;
    }();
}
