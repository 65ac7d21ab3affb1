#include "app/web/movie_archive.h"
#include "app/wall_output.h"

#include <zlib.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace aurorawall::app::web {

namespace {

namespace fs = std::filesystem;

// The zip format's numbers: little-endian, of 2, 4 or 8 bytes (PKWARE's APPNOTE.TXT 6.3, 4.3).
void put(std::string& out, std::uint64_t value, int bytes)
{
    for (int i = 0; i < bytes; ++i)
        out += char((value >> (8 * i)) & 0xff);
}

constexpr std::uint32_t kLocalHeader = 0x04034b50, kCentralHeader = 0x02014b50, kEnd = 0x06054b50;
constexpr std::uint32_t kZip64End = 0x06064b50, kZip64Locator = 0x07064b50;
constexpr std::uint64_t kMax32 = 0xffffffffu; // a 4-byte field at this value: see the zip64 extra field
constexpr int kVersion = 45;                  // 4.5: zip64 (also read by every unzip of the last 20 years)

struct Entry {
    std::string name;
    std::uint64_t bytes = 0;
    std::uint32_t crc = 0;
    std::uint16_t dosTime = 0, dosDate = 0;
    std::uint64_t offset = 0; // of its local header
};

// MS-DOS date and time (local, 2 s steps), as zip keeps them; 1980 at the earliest.
void setDosTime(Entry& e, std::time_t t)
{
    std::tm local{};
    localtime_r(&t, &local);
    if (local.tm_year < 80) { // 1980-01-01 00:00
        local = std::tm{};
        local.tm_mday = 1;
        local.tm_year = 80;
    }
    e.dosTime = std::uint16_t(local.tm_hour << 11 | local.tm_min << 5 | local.tm_sec / 2);
    e.dosDate = std::uint16_t((local.tm_year - 80) << 9 | (local.tm_mon + 1) << 5 | local.tm_mday);
}

// The fields a local header and a central directory header share, from the version needed to
// extract to the name's length; `big`: the sizes are in the zip64 extra field.
void putSharedFields(std::string& h, const Entry& e, bool big)
{
    put(h, kVersion, 2);
    put(h, 0, 2); // flags
    put(h, 0, 2); // stored
    put(h, e.dosTime, 2);
    put(h, e.dosDate, 2);
    put(h, e.crc, 4);
    put(h, big ? kMax32 : e.bytes, 4);
    put(h, big ? kMax32 : e.bytes, 4);
    put(h, e.name.size(), 2);
}

// A local header: stored (method 0), CRC-32 and sizes known before the data (no data descriptor),
// sizes past 4 GiB in a zip64 extra field.
std::string localHeader(const Entry& e)
{
    const bool big = e.bytes >= kMax32;
    std::string h;
    put(h, kLocalHeader, 4);
    putSharedFields(h, e, big);
    put(h, big ? 20 : 0, 2);
    h += e.name;
    if (big) {
        put(h, 0x0001, 2);
        put(h, 16, 2);
        put(h, e.bytes, 8);
        put(h, e.bytes, 8);
    }
    return h;
}

std::string centralHeader(const Entry& e)
{
    const bool big = e.bytes >= kMax32, far = e.offset >= kMax32;
    const int extra = (big ? 16 : 0) + (far ? 8 : 0);
    std::string h;
    put(h, kCentralHeader, 4);
    put(h, 3 << 8 | kVersion, 2); // made on Unix: the external attributes are a mode
    putSharedFields(h, e, big);
    put(h, extra ? extra + 4 : 0, 2);
    put(h, 0, 2);                        // comment
    put(h, 0, 2);                        // disk
    put(h, 0, 2);                        // internal attributes
    put(h, std::uint64_t(0100644) << 16, 4); // a regular file, rw-r--r--
    put(h, far ? kMax32 : e.offset, 4);
    h += e.name;
    if (extra) {
        put(h, 0x0001, 2);
        put(h, extra, 2);
        if (big) {
            put(h, e.bytes, 8);
            put(h, e.bytes, 8);
        }
        if (far)
            put(h, e.offset, 8);
    }
    return h;
}

// The end: a zip64 end record and its locator where a count or offset does not fit the classic one.
std::string end(std::uint64_t entries, std::uint64_t directoryOffset, std::uint64_t directoryBytes)
{
    std::string h;
    const bool zip64 = entries >= 0xffff || directoryOffset >= kMax32 || directoryBytes >= kMax32;
    if (zip64) {
        const std::uint64_t at = directoryOffset + directoryBytes;
        put(h, kZip64End, 4);
        put(h, 44, 8);
        put(h, 3 << 8 | kVersion, 2);
        put(h, kVersion, 2);
        put(h, 0, 4);
        put(h, 0, 4);
        put(h, entries, 8);
        put(h, entries, 8);
        put(h, directoryBytes, 8);
        put(h, directoryOffset, 8);
        put(h, kZip64Locator, 4);
        put(h, 0, 4);
        put(h, at, 8);
        put(h, 1, 4);
    }
    put(h, kEnd, 4);
    put(h, 0, 2);
    put(h, 0, 2);
    put(h, zip64 ? 0xffff : entries, 2);
    put(h, zip64 ? 0xffff : entries, 2);
    put(h, zip64 ? kMax32 : directoryBytes, 4);
    put(h, zip64 ? kMax32 : directoryOffset, 4);
    put(h, 0, 2);
    return h;
}

struct FileClose {
    int fd;
    ~FileClose() { ::close(fd); }
};

// Reads the whole of an open file in blocks: each handed to `use`; "" or why it stopped.
template <typename Use>
std::string readAll(int fd, const std::string& path, std::uint64_t bytes, std::vector<char>& buffer, Use use)
{
    if (::lseek(fd, 0, SEEK_SET) != 0)
        return path + ": " + std::strerror(errno);
    std::uint64_t left = bytes;
    while (left > 0) {
        const ssize_t got = ::read(fd, buffer.data(), std::min<std::uint64_t>(left, buffer.size()));
        if (got < 0 && errno == EINTR)
            continue;
        if (got <= 0)
            return path + ": " + (got < 0 ? std::strerror(errno) : "shorter than when listed");
        if (!use(buffer.data(), std::size_t(got)))
            return kClientGone;
        left -= std::uint64_t(got);
    }
    return "";
}

} // namespace

std::vector<MovieFile> movieFiles(const std::string& folder)
{
    std::vector<MovieFile> files;
    std::error_code error;
    fs::directory_iterator it(folder, error);
    if (error)
        throw std::runtime_error(folder + ": " + error.message());
    for (; it != fs::directory_iterator(); it.increment(error)) {
        const std::string name = it->path().filename().string();
        std::error_code statError;
        if (!MovieWriter::writes(name) || !fs::is_regular_file(it->symlink_status(statError)))
            continue;
        const std::uintmax_t bytes = fs::file_size(it->path(), statError);
        if (!statError)
            files.push_back({name, bytes});
    }
    if (error)
        throw std::runtime_error(folder + ": " + error.message());
    std::sort(files.begin(), files.end(), [](const MovieFile& a, const MovieFile& b) { return a.name < b.name; });
    return files;
}

// Each file is read twice: once for its CRC-32, which the local header carries ahead of the data (a
// zip any unzip takes, with no data descriptor), then sent, its CRC checked again on the way.
std::string writeMovieZip(const std::string& folder, const std::vector<MovieFile>& files, const std::string& top,
                          const std::function<bool(const char* data, std::size_t bytes)>& write)
{
    std::vector<char> buffer(65536);
    std::vector<Entry> entries;
    std::uint64_t offset = 0;
    const auto send = [&](const std::string& bytes) {
        offset += bytes.size();
        return write(bytes.data(), bytes.size());
    };
    for (const MovieFile& f : files) {
        const std::string path = folder + "/" + f.name;
        const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
        if (fd < 0)
            return path + ": " + std::strerror(errno);
        FileClose closer{fd};
        struct stat st {};
        if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || std::uintmax_t(st.st_size) != f.bytes)
            return path + ": changed while the movie was being sent";
        Entry e{top + "/" + f.name, f.bytes, 0, 0, 0, offset};
        setDosTime(e, st.st_mtim.tv_sec);
        uLong crc = crc32(0L, Z_NULL, 0);
        std::string error = readAll(fd, path, f.bytes, buffer, [&crc](const char* data, std::size_t n) {
            crc = crc32(crc, reinterpret_cast<const Bytef*>(data), uInt(n));
            return true;
        });
        if (!error.empty())
            return error;
        e.crc = std::uint32_t(crc);
        if (!send(localHeader(e)))
            return kClientGone;
        uLong again = crc32(0L, Z_NULL, 0);
        error = readAll(fd, path, f.bytes, buffer, [&](const char* data, std::size_t n) {
            again = crc32(again, reinterpret_cast<const Bytef*>(data), uInt(n));
            offset += n;
            return write(data, n);
        });
        if (!error.empty())
            return error;
        if (again != crc)
            return path + ": changed while the movie was being sent";
        entries.push_back(std::move(e));
    }
    const std::uint64_t directoryOffset = offset;
    for (const Entry& e : entries)
        if (!send(centralHeader(e)))
            return kClientGone;
    if (!send(end(entries.size(), directoryOffset, offset - directoryOffset)))
        return kClientGone;
    return "";
}

} // namespace aurorawall::app::web
