#include "app/web/downloads.h"

#include "config/toml_string.h"

#include <filesystem>
#include <optional>
#include <sstream>

namespace aurorawall::app::web {

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
            if (const std::optional<std::string> base = config::tomlBasicStringValue(line.substr(key.size()))) {
                std::filesystem::path path(*base);
                if (path.is_relative())
                    path = std::filesystem::absolute(std::filesystem::path(folder) / path).lexically_normal();
                line = key + config::tomlBasicString(path.generic_string());
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
