#include "io/directory.h"

#include "common/input_error.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <system_error>
#include <unistd.h>

namespace aurorawall::io {

namespace {

// Permission bits alone do not tell (root, read-only mounts, ACLs): create and remove a file there.
void probeWritable(const std::string& dir, const std::string& where)
{
    const std::string probe = (std::filesystem::path(dir) / (".aurorawall-probe-" + std::to_string(::getpid()))).string();
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd < 0)
        throw common::InputError(where + "directory is not writable (" + std::strerror(errno) + ")");
    ::close(fd);
    ::unlink(probe.c_str());
}

} // namespace

void ensureWritableDirectory(const std::string& dir, const std::string& optionName)
{
    const std::string where = optionName + " " + dir + ": ";
    std::error_code error;
    std::filesystem::create_directories(dir, error);
    if (error)
        throw common::InputError(where + "cannot create directory (" + error.message() + ")");
    if (!std::filesystem::is_directory(dir, error))
        throw common::InputError(where + "not a directory");
    probeWritable(dir, where);
}

void ensureWritableFile(const std::string& path, const std::string& optionName)
{
    const std::string where = optionName + " " + path + ": ";
    std::error_code error;
    if (std::filesystem::is_directory(path, error))
        throw common::InputError(where + "is a folder, not a file");
    if (std::filesystem::exists(path, error) && !std::filesystem::is_regular_file(path, error))
        throw common::InputError(where + "exists and is not a file");
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    const std::string dir = parent.empty() ? "." : parent.string();
    if (!std::filesystem::is_directory(dir, error))
        throw common::InputError(where + "folder " + dir + " does not exist");
    probeWritable(dir, where + "folder " + dir + ": ");
}

} // namespace aurorawall::io
