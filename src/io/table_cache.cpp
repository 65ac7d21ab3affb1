#include "io/table_cache.h"

#include "io/atomic_file.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <utility>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace aurorawall::io {

namespace {

// File layout, native byte order (a cache is read by the build that wrote it):
//   "AWTABLE1" | u64 key size | key | u64 table size | table | u64 FNV-1a of everything before it
constexpr char kMagic[8] = {'A', 'W', 'T', 'A', 'B', 'L', 'E', '1'};

void append(std::vector<char>& out, const void* data, std::size_t size)
{
    const char* bytes = static_cast<const char*>(data);
    out.insert(out.end(), bytes, bytes + size);
}

void appendSize(std::vector<char>& out, std::uint64_t size) { append(out, &size, sizeof size); }

std::vector<char> encode(const std::string& key, const std::vector<char>& table)
{
    std::vector<char> out;
    out.reserve(sizeof kMagic + 3 * sizeof(std::uint64_t) + key.size() + table.size());
    append(out, kMagic, sizeof kMagic);
    appendSize(out, key.size());
    append(out, key.data(), key.size());
    appendSize(out, table.size());
    append(out, table.data(), table.size());
    const std::uint64_t checksum = fnv1a64(out.data(), out.size());
    append(out, &checksum, sizeof checksum);
    return out;
}

enum class Decoded { Table, OtherKey, Corrupt };

// Checks the layout and the checksum; on success moves the table into `table`.
Decoded decode(const std::vector<char>& file, const std::string& key, std::vector<char>& table)
{
    std::size_t at = 0;
    const auto readSize = [&](std::uint64_t& size) {
        if (file.size() - at < sizeof size)
            return false;
        std::memcpy(&size, file.data() + at, sizeof size);
        at += sizeof size;
        return true;
    };
    std::uint64_t keySize = 0, tableSize = 0, checksum = 0;
    if (file.size() < sizeof kMagic || std::memcmp(file.data(), kMagic, sizeof kMagic) != 0)
        return Decoded::Corrupt;
    at = sizeof kMagic;
    if (!readSize(keySize) || file.size() - at < keySize)
        return Decoded::Corrupt;
    const std::size_t keyAt = at;
    at += keySize;
    if (!readSize(tableSize) || file.size() - at < tableSize)
        return Decoded::Corrupt;
    const std::size_t tableAt = at;
    at += tableSize;
    const std::size_t checked = at;
    if (!readSize(checksum) || at != file.size() || checksum != fnv1a64(file.data(), checked))
        return Decoded::Corrupt;
    if (std::string(file.data() + keyAt, keySize) != key)
        return Decoded::OtherKey; // another key with the same 64-bit hash: not this table
    table.assign(file.begin() + static_cast<std::ptrdiff_t>(tableAt),
                 file.begin() + static_cast<std::ptrdiff_t>(tableAt + tableSize));
    return Decoded::Table;
}

std::optional<std::vector<char>> readFile(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return std::nullopt;
    std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad())
        return std::nullopt;
    return bytes;
}

// Keeps the newest kKeptPerName files of `name` in the folder and removes the older ones, so that
// rebuilds (each a new executable digest, so a new key) do not fill the disk. Best effort: a file
// another process removes first, or cannot be removed, is left to the next write.
constexpr std::size_t kKeptPerName = 8;

void removeOldFiles(const std::string& directory, const std::string& name)
{
    namespace fs = std::filesystem;
    std::error_code error;
    std::vector<std::pair<fs::file_time_type, fs::path>> files;
    for (const fs::directory_entry& entry : fs::directory_iterator(directory, error)) {
        const std::string file = entry.path().filename().string();
        const bool ofName = file.size() == name.size() + 1 + 16 + 6 && file.rfind(name + "-", 0) == 0 &&
                            entry.path().extension() == ".table"; // "<name>-<16 hex digits>.table"
        if (ofName) {
            const fs::file_time_type written = entry.last_write_time(error);
            if (!error)
                files.emplace_back(written, entry.path());
        }
    }
    if (files.size() <= kKeptPerName)
        return;
    std::sort(files.begin(), files.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    for (std::size_t i = kKeptPerName; i < files.size(); ++i) {
        fs::remove(files[i].second, error);
        fs::remove(files[i].second.string() + ".lock", error);
    }
}

// An exclusive advisory lock (flock) on a file beside the table, held while one process builds it:
// the other ranks of a node wait, then read what it wrote, instead of all building the same table
// on shared cores. Where locks are not available (a file system without them), it holds nothing and
// every process builds, as without it.
class BuildLock {
public:
    explicit BuildLock(const std::string& path) : fd_(::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644))
    {
        if (fd_ >= 0 && ::flock(fd_, LOCK_EX) != 0) {
            ::close(fd_);
            fd_ = -1;
        }
    }
    BuildLock(const BuildLock&) = delete;
    BuildLock& operator=(const BuildLock&) = delete;
    ~BuildLock()
    {
        if (fd_ >= 0)
            ::close(fd_); // releases the lock
    }

private:
    int fd_;
};

std::string hex16(std::uint64_t value)
{
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
    return text;
}

} // namespace

std::uint64_t fnv1a64(const void* data, std::size_t size, std::uint64_t hash)
{
    const unsigned char* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
        hash ^= bytes[i];
        hash *= 0x100000001b3ull;
    }
    return hash;
}

std::string defaultCacheDirectory()
{
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
        return (std::filesystem::path(xdg) / "aurorawall").string();
    if (const char* home = std::getenv("HOME"); home && *home)
        return (std::filesystem::path(home) / ".cache" / "aurorawall").string();
    return {};
}

const std::string& executableDigest()
{
    static const std::string digest = [] {
        const std::optional<std::vector<char>> exe = readFile("/proc/self/exe");
        if (!exe)
            throw std::runtime_error("/proc/self/exe: cannot read the executable for its digest");
        return hex16(fnv1a64(exe->data(), exe->size()));
    }();
    return digest;
}

std::string cachedTablePath(const std::string& directory, const std::string& name, const std::string& key)
{
    return (std::filesystem::path(directory) / (name + "-" + hex16(fnv1a64(key.data(), key.size())) + ".table")).string();
}

CachedTable cachedTable(const std::string& directory, const std::string& name, const std::string& key,
                        const std::function<std::vector<char>()>& build)
{
    CachedTable result;
    if (directory.empty()) {
        result.bytes = build();
        result.outcome = "built, not cached (no cache folder: neither XDG_CACHE_HOME nor HOME is set)";
        return result;
    }
    const std::string path = cachedTablePath(directory, name, key);
    bool corrupt = false;
    // Returns whether a good table was read.
    const auto read = [&] {
        if (const std::optional<std::vector<char>> file = readFile(path)) {
            const Decoded decoded = decode(*file, key, result.bytes);
            if (decoded == Decoded::Table)
                return true;
            corrupt = decoded == Decoded::Corrupt;
        }
        return false;
    };
    if (read()) {
        result.outcome = "read from cache";
        return result;
    }
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    const BuildLock lock(path + ".lock");
    if (read()) { // another process built it while this one waited
        result.outcome = "read from cache, built by another process";
        return result;
    }
    result.bytes = build();
    result.outcome = corrupt ? "cache corrupt, rebuilt" : "built, cached";
    try {
        std::filesystem::create_directories(directory);
        const std::vector<char> file = encode(key, result.bytes);
        writeFileAtomically(path, [&](const std::string& temporary) {
            std::ofstream out(temporary, std::ios::binary);
            out.write(file.data(), static_cast<std::streamsize>(file.size()));
            if (!out.flush())
                throw std::runtime_error(temporary + ": cannot write");
        });
        removeOldFiles(directory, name);
    } catch (const std::exception& e) {
        result.outcome = (corrupt ? "cache corrupt, rebuilt, not cached (" : "built, not cached (") +
                         std::string(e.what()) + ")";
    }
    return result;
}

} // namespace aurorawall::io
