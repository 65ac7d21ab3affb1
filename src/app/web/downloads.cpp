#include "app/web/downloads.h"

#include <filesystem>
#include <optional>
#include <sstream>

namespace aurorawall::app::web {

namespace {

// The value of a TOML basic string holding only the escapes \" and \\ (as PathRecorder writes).
std::optional<std::string> unquoted(const std::string& s)
{
    if (s.size() < 2 || s.front() != '"' || s.back() != '"')
        return std::nullopt;
    std::string value;
    for (size_t i = 1; i + 1 < s.size(); ++i) {
        char c = s[i];
        if (c == '\\') {
            if (i + 2 >= s.size() || (s[i + 1] != '"' && s[i + 1] != '\\'))
                return std::nullopt;
            c = s[++i];
        } else if (c == '"') {
            return std::nullopt;
        }
        value += c;
    }
    return value;
}

std::string quoted(const std::string& s)
{
    std::string q = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\')
            q += '\\';
        q += c;
    }
    return q + "\"";
}

} // namespace

std::string recordingForDownload(const std::string& text, const std::string& folder)
{
    const std::string key = "base = ";
    std::istringstream in(text);
    std::string out, line, table;
    bool done = false;
    while (std::getline(in, line)) {
        if (!line.empty() && line.front() == '[')
            table = line;
        if (!done && table == "[scene]" && line.compare(0, key.size(), key) == 0) {
            if (const std::optional<std::string> base = unquoted(line.substr(key.size()))) {
                std::filesystem::path path(*base);
                if (path.is_relative())
                    path = std::filesystem::absolute(std::filesystem::path(folder) / path).lexically_normal();
                line = key + quoted(path.generic_string());
                done = true;
            }
        }
        out += line + "\n";
    }
    if (!text.empty() && text.back() != '\n')
        out.pop_back(); // as it was
    return out;
}

} // namespace aurorawall::app::web
