// Rules every source file keeps (a scan of src/):
// - No function is longer than 80 lines, so that each does one job that fits on a screen. A function's
//   body is found by the project's layout: its opening brace alone on a line (at the function's
//   indentation, after the line that ends its signature) and its closing brace at the same
//   indentation; its length counts from the signature's last line to the closing brace.
// - Namespaces match folders: every named namespace block in src/X/Y/ is aurorawall::X::Y, so that a
//   name tells where it is defined. Unnamed namespaces and namespace aliases are free, and so are the
//   precision namespaces f32 and f64 under the folder's (aurorawall::X::Y::f64), into which shared
//   GLSL modules are compiled as C++ (common/glsl.h).
// - Components are found by role, never by name: no component (the list of the registry,
//   src/components/CMakeLists.txt) is named in src/scene, src/render, src/app, shaders/render or
//   another component's folders (src/ and shaders/), comments included. Naming is a reference a
//   program can follow: its folder ("components/NAME/"), its name as a string ("NAME"), its
//   namespace ("NAME::") or its shader define (HAS_NAME); the words of physics (the planet frame,
//   the lower atmosphere) are not.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <set>
#include <string>
#include <utility>
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


// The source text with its comments and its string and character literals (raw strings included)
// blanked out, newlines kept: what is left is code, whose braces can be counted.
std::string codeOnly(const std::string& text)
{
    std::string code = text;
    auto blank = [&](std::size_t from, std::size_t to) {
        for (std::size_t k = from; k < to && k < code.size(); ++k)
            if (code[k] != '\n')
                code[k] = ' ';
    };
    std::size_t i = 0;
    while (i < text.size()) {
        std::size_t end = i + 1;
        if (text.compare(i, 2, "//") == 0) {
            end = text.find('\n', i);
        } else if (text.compare(i, 2, "/*") == 0) {
            end = text.find("*/", i + 2);
            end = end == std::string::npos ? end : end + 2;
        } else if (text.compare(i, 2, "R\"") == 0 && (i == 0 || !std::isalnum(static_cast<unsigned char>(text[i - 1])))) {
            const std::size_t open = text.find('(', i);
            const std::string close = ")" + text.substr(i + 2, open - i - 2) + "\"";
            end = text.find(close, open);
            end = end == std::string::npos ? end : end + close.size();
        } else if (text[i] == '"' || (text[i] == '\'' && (i == 0 || !std::isalnum(static_cast<unsigned char>(text[i - 1]))))) {
            end = i + 1;
            while (end < text.size() && text[end] != text[i] && text[end] != '\n')
                end += text[end] == '\\' ? 2 : 1;
            ++end;
        } else {
            ++i;
            continue;
        }
        end = std::min(end, text.size());
        blank(i, end);
        i = end;
    }
    return code;
}

struct NamespaceBlock {
    std::string file;
    int line;
    std::string name; // with the names of the named blocks around it
};

// The named namespace blocks of `file`: a line that opens a block "namespace NAME {" (not an alias).
std::vector<NamespaceBlock> namedNamespaces(const std::filesystem::path& file)
{
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    std::istringstream code(codeOnly(text.str()));
    static const std::regex opening(R"(^\s*(inline\s+)?namespace\s*([A-Za-z_][A-Za-z_0-9:]*)?\s*\{)");
    struct Open {
        std::string name; // empty: unnamed
        int depth;        // the brace depth outside it
    };
    std::vector<Open> open;
    std::vector<NamespaceBlock> found;
    int depth = 0, number = 0;
    for (std::string line; std::getline(code, line);) {
        ++number;
        std::smatch m;
        if (std::regex_search(line, m, opening)) {
            std::string name;
            for (const Open& o : open)
                name += o.name.empty() ? "" : (name.empty() ? "" : "::") + o.name;
            if (m[2].matched) {
                name += (name.empty() ? "" : "::") + m[2].str();
                found.push_back({std::filesystem::relative(file, kSource).string(), number, name});
            }
            open.push_back({m[2].str(), depth});
        }
        for (char c : line) {
            if (c == '{')
                ++depth;
            else if (c == '}' && --depth >= 0 && !open.empty() && open.back().depth == depth)
                open.pop_back();
        }
    }
    return found;
}

// src/X/Y -> aurorawall::X::Y
std::string folderNamespace(const std::filesystem::path& folder)
{
    std::string name = "aurorawall";
    for (const auto& part : std::filesystem::relative(folder, kSource / "src"))
        if (part != ".")
            name += "::" + part.string();
    return name;
}

// The registered components: the list in src/components/CMakeLists.txt.
std::vector<std::string> componentNames()
{
    const std::string key = "set(AURORAWALL_COMPONENTS ";
    for (const std::string& line : lines(kSource / "src/components/CMakeLists.txt"))
        if (line.rfind(key, 0) == 0) {
            std::istringstream words(line.substr(key.size(), line.find(')') - key.size()));
            std::vector<std::string> names;
            for (std::string name; words >> name;)
                names.push_back(name);
            return names;
        }
    return {};
}

bool isWordCharacter(char c)
{
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

// Does `line` name the component `name`: "components/NAME/", "components::NAME::", "\"NAME\"", or as
// a word "NAME::" or "HAS_NAME"?
bool namesComponent(const std::string& line, const std::string& name)
{
    std::string define = "HAS_" + name;
    for (char& c : define)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    for (const std::string& reference : {"components/" + name + "/", "components::" + name + "::", "\"" + name + "\""})
        if (line.find(reference) != std::string::npos)
            return true;
    for (const std::string& word : {name + "::", define})
        for (std::size_t at = line.find(word); at != std::string::npos; at = line.find(word, at + 1)) {
            const std::size_t end = at + word.size();
            const bool before = at > 0 && (isWordCharacter(line[at - 1]) || line[at - 1] == ':');
            const bool after = word == define && end < line.size() && isWordCharacter(line[end]);
            if (!before && !after)
                return true;
        }
    return false;
}

// The files under `folder` (relative to the source tree) that name a component other than `own`,
// as "file: component".
std::set<std::string> componentsNamed(const std::string& folder, const std::vector<std::string>& names, const std::string& own)
{
    std::set<std::string> found;
    if (!std::filesystem::is_directory(kSource / folder))
        return found;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(kSource / folder)) {
        if (!entry.is_regular_file())
            continue;
        for (const std::string& line : lines(entry.path()))
            for (const std::string& name : names)
                if (name != own && namesComponent(line, name))
                    found.insert(std::filesystem::relative(entry.path(), kSource).string() + ": " + name);
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

TEST(SourceRules, NamespacesMatchFolders)
{
    std::size_t files = 0, blocks = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(kSource / "src")) {
        const std::string extension = entry.path().extension().string();
        if (!entry.is_regular_file() || (extension != ".cpp" && extension != ".h" && extension != ".in"))
            continue;
        ++files;
        const std::string expected = folderNamespace(entry.path().parent_path());
        for (const NamespaceBlock& b : namedNamespaces(entry.path())) {
            ++blocks;
            if (b.name != expected && b.name != expected + "::f32" && b.name != expected + "::f64")
                ADD_FAILURE() << b.file << ":" << b.line << ": namespace " << b.name << ", in a folder of " << expected;
        }
    }
    EXPECT_GT(files, 100u);
    EXPECT_GT(blocks, 300u); // the scan finds the blocks at all
}

TEST(SourceRules, NoComponentIsNamedOutsideItsFolders)
{
    const std::vector<std::string> names = componentNames();
    ASSERT_GE(names.size(), 5u);
    std::set<std::string> named;
    for (const char* core : {"src/scene", "src/render", "src/app", "shaders/render"})
        named.merge(componentsNamed(core, names, ""));
    for (const std::string& component : names) {
        named.merge(componentsNamed("src/components/" + component, names, component));
        named.merge(componentsNamed("shaders/components/" + component, names, component));
    }
    for (const std::string& n : named)
        ADD_FAILURE() << n << ": a component named outside its folders (find it by a role)";
}
