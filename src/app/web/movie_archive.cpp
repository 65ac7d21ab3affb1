#include "app/web/movie_archive.h"

#include <archive.h>
#include <archive_entry.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <memory>
#include <regex>
#include <stdexcept>
#include <system_error>

namespace aurorawall::app::web {

namespace {

namespace fs = std::filesystem;

bool movieFileName(const std::string& name)
{
    static const std::regex frame(R"(frame-[0-9]{6,20}\.(png|exr))");
    return name == "frames.csv" || std::regex_match(name, frame);
}

struct Output {
    const std::function<bool(const char*, std::size_t)>* write;
    bool clientGone = false;
};

la_ssize_t toClient(struct archive*, void* data, const void* buffer, size_t bytes)
{
    Output& out = *static_cast<Output*>(data);
    if (!(*out.write)(static_cast<const char*>(buffer), bytes)) {
        out.clientGone = true;
        return -1;
    }
    return static_cast<la_ssize_t>(bytes);
}

struct ArchiveFree {
    void operator()(struct archive* a) const { archive_write_free(a); }
};
struct EntryFree {
    void operator()(struct archive_entry* e) const { archive_entry_free(e); }
};
struct FileClose {
    int fd;
    ~FileClose() { ::close(fd); }
};

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
        if (!movieFileName(name) || !fs::is_regular_file(it->symlink_status(statError)))
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

std::string writeMovieZip(const std::string& folder, const std::vector<MovieFile>& files, const std::string& top,
                          const std::function<bool(const char* data, std::size_t bytes)>& write)
{
    Output out{&write};
    std::unique_ptr<struct archive, ArchiveFree> a(archive_write_new());
    if (!a)
        return "libarchive: out of memory";
    const auto failed = [&](const std::string& what) {
        if (out.clientGone)
            return std::string(kClientGone);
        const char* reason = archive_error_string(a.get());
        return what + ": " + (reason ? reason : "libarchive failed");
    };
    // Stored: PNG and OpenEXR are compressed already. Written in 64 KiB blocks, the last one unpadded.
    if (archive_write_set_format_zip(a.get()) != ARCHIVE_OK ||
        archive_write_set_options(a.get(), "zip:compression=store") != ARCHIVE_OK ||
        archive_write_set_bytes_per_block(a.get(), 65536) != ARCHIVE_OK ||
        archive_write_set_bytes_in_last_block(a.get(), 1) != ARCHIVE_OK ||
        archive_write_open(a.get(), &out, nullptr, toClient, nullptr) != ARCHIVE_OK)
        return failed("zip");
    std::vector<char> buffer(65536);
    for (const MovieFile& f : files) {
        const std::string path = folder + "/" + f.name;
        const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
        if (fd < 0)
            return path + ": " + std::strerror(errno);
        FileClose closer{fd};
        struct stat st {};
        if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || std::uintmax_t(st.st_size) != f.bytes)
            return path + ": changed while the movie was being sent";
        std::unique_ptr<struct archive_entry, EntryFree> entry(archive_entry_new());
        archive_entry_set_pathname(entry.get(), (top + "/" + f.name).c_str());
        archive_entry_set_filetype(entry.get(), AE_IFREG);
        archive_entry_set_perm(entry.get(), 0644);
        archive_entry_set_size(entry.get(), la_int64_t(f.bytes));
        archive_entry_set_mtime(entry.get(), st.st_mtim.tv_sec, st.st_mtim.tv_nsec);
        if (archive_write_header(a.get(), entry.get()) != ARCHIVE_OK)
            return failed(f.name);
        std::uintmax_t left = f.bytes;
        while (left > 0) {
            const ssize_t got = ::read(fd, buffer.data(), std::min<std::uintmax_t>(left, buffer.size()));
            if (got < 0 && errno == EINTR)
                continue;
            if (got <= 0)
                return path + ": " + (got < 0 ? std::strerror(errno) : "shorter than when listed");
            if (archive_write_data(a.get(), buffer.data(), size_t(got)) != got)
                return failed(f.name);
            left -= std::uintmax_t(got);
        }
        if (archive_write_finish_entry(a.get()) != ARCHIVE_OK)
            return failed(f.name);
    }
    if (archive_write_close(a.get()) != ARCHIVE_OK)
        return failed("zip");
    return "";
}

} // namespace aurorawall::app::web
