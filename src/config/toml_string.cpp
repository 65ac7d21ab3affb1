#include "config/toml_string.h"

namespace aurorawall::config {

std::string tomlBasicString(const std::string& s)
{
    std::string q = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\')
            q += '\\';
        q += c;
    }
    return q + "\"";
}

std::optional<std::string> tomlBasicStringValue(const std::string& text)
{
    if (text.size() < 2 || text.front() != '"' || text.back() != '"')
        return std::nullopt;
    std::string value;
    for (size_t i = 1; i + 1 < text.size(); ++i) {
        char c = text[i];
        if (c == '\\') {
            if (i + 2 >= text.size() || (text[i + 1] != '"' && text[i + 1] != '\\'))
                return std::nullopt;
            c = text[++i];
        } else if (c == '"') {
            return std::nullopt;
        }
        value += c;
    }
    return value;
}

} // namespace aurorawall::config
