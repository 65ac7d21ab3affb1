#include "app/control/output_path.h"

#include "app/control/command.h"

namespace aurorawall::app::control {

std::filesystem::path insideOutputFolder(const std::string& what, const std::string& path,
                                         const std::string& outputDir)
{
    const std::filesystem::path relative(path);
    if (relative.is_absolute())
        throw CommandError(what + ": an absolute path; give a path inside the output folder (--out " + outputDir + ")");
    for (const std::filesystem::path& part : relative)
        if (part == "..")
            throw CommandError(what + ": '..' would leave the output folder (--out " + outputDir + ")");
    const std::filesystem::path full = std::filesystem::path(outputDir) / relative;
    std::error_code error;
    if (!std::filesystem::is_directory(full.parent_path(), error))
        throw CommandError(what + ": " + full.parent_path().string() + " is not a folder");
    return full;
}

} // namespace aurorawall::app::control
