// A rule every source file keeps (a scan of src/): no function is longer than 80 lines, so that each
// does one job that fits on a screen. A function's body is found by the project's layout: its opening
// brace alone on a line (at the function's indentation, after the line that ends its signature) and
// its closing brace at the same indentation; its length counts from the signature's last line to the
// closing brace.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

const std::filesystem::path kSource = AURORAWALL_SOURCE_DIR;
constexpr int kMaxLines = 80;

struct LongFunction {
    std::string file;
    int line;
    int length;
};

std::vector<std::string> lines(const std::filesystem::path& file)
{
    std::ifstream in(file);
    std::vector<std::string> all;
    for (std::string line; std::getline(in, line);)
        all.push_back(line);
    return all;
}

std::size_t indentation(const std::string& line)
{
    return line.find_first_not_of(' ');
}

// A line that is only "{" after a line that ends a signature: "...)" maybe followed by qualifiers.
bool opensFunction(const std::vector<std::string>& text, std::size_t i)
{
    const std::size_t at = indentation(text[i]);
    if (i == 0 || at == std::string::npos || text[i].substr(at) != "{")
        return false;
    const std::string& before = text[i - 1];
    const std::size_t close = before.rfind(')');
    if (close == std::string::npos || indentation(before) != at)
        return false;
    const std::string after = before.substr(close + 1);
    return after.find_first_not_of(" constoverridnexcept&") == std::string::npos;
}

std::vector<LongFunction> longFunctions(const std::filesystem::path& file)
{
    const std::vector<std::string> text = lines(file);
    std::vector<LongFunction> found;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (!opensFunction(text, i))
            continue;
        const std::string closing = std::string(indentation(text[i]), ' ') + "}";
        std::size_t end = i + 1;
        while (end < text.size() && text[end].rfind(closing, 0) != 0)
            ++end;
        const int length = static_cast<int>(end - i) + 2; // the signature's last line to the closing brace
        if (length > kMaxLines)
            found.push_back({std::filesystem::relative(file, kSource).string(), static_cast<int>(i), length});
        i = end;
    }
    return found;
}

} // namespace

TEST(SourceRules, NoFunctionInSrcIsLongerThan80Lines)
{
    std::vector<LongFunction> offenders;
    std::size_t functions = 0, files = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(kSource / "src")) {
        const std::string extension = entry.path().extension().string();
        if (!entry.is_regular_file() || (extension != ".cpp" && extension != ".h"))
            continue;
        ++files;
        const std::vector<std::string> text = lines(entry.path());
        for (std::size_t i = 0; i < text.size(); ++i)
            functions += opensFunction(text, i) ? 1 : 0;
        for (const LongFunction& f : longFunctions(entry.path()))
            offenders.push_back(f);
    }
    EXPECT_GT(files, 100u);
    EXPECT_GT(functions, 1000u); // the layout rule finds the functions at all
    for (const LongFunction& f : offenders)
        ADD_FAILURE() << f.file << ":" << f.line << ": a function of " << f.length << " lines";
}
