#include "common/data_dir.h"

#include <cstdlib>
#include <filesystem>

namespace aurorawall::common {

std::string dataDirectory()
{
    namespace fs = std::filesystem;
    if (const char* env = std::getenv("AURORAWALL_DATA_DIR"); env && *env)
        return env;
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const fs::path installed = exe.parent_path().parent_path() / "share" / "aurorawall";
        if (fs::is_directory(installed / "shaders", ec))
            return installed.string();
    }
    return AURORAWALL_SOURCE_DATA_DIR;
}

} // namespace aurorawall::common
