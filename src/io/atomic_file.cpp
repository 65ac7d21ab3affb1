#include "io/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <stdexcept>
#include <unistd.h>

namespace aurorawall::io {

namespace {

std::runtime_error systemError(const std::string& path, const std::string& what)
{
    return std::runtime_error(path + ": " + what + " (" + std::strerror(errno) + ")");
}

// fsync before rename, or after a power loss the new name may point at an empty file
// (the ext4/XFS "zero-length file" problem).
void syncToDisk(const std::string& path)
{
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        throw systemError(path, "cannot open to sync");
    const bool synced = ::fsync(fd) == 0;
    ::close(fd);
    if (!synced)
        throw systemError(path, "cannot sync to disk");
}

} // namespace

std::string temporaryPathFor(const std::string& path)
{
    const std::filesystem::path p(path);
    const std::string name = "." + p.filename().string() + ".tmp-" + std::to_string(::getpid());
    return (p.parent_path() / name).string();
}

void writeFileAtomically(const std::string& path,
                         const std::function<void(const std::string& temporaryPath)>& writeTemporary)
{
    const std::string temporary = temporaryPathFor(path);
    try {
        writeTemporary(temporary);
        syncToDisk(temporary);
        if (std::rename(temporary.c_str(), path.c_str()) != 0)
            throw systemError(path, "cannot rename " + temporary + " to it");
    } catch (...) {
        std::remove(temporary.c_str());
        throw;
    }
}

} // namespace aurorawall::io
