#pragma once
// GET /movies/NAME: a finished movie's folder as one zip, streamed. The frames are PNG (and OpenEXR),
// already compressed, so they are stored as they are (method 0; zip64 past 4 GiB or 65535 files;
// CRC-32 from zlib), one file and 64 KiB at a time, so a movie of any length never sits in memory.
// Not libarchive: its Debian build pulls libxml2 and ICU (31 MB) into the binary, past what
// launch/gpu-bundle may carry to a GPU node; a stored zip is a few fixed-layout records.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace aurorawall::app::web {

struct MovieFile {
    std::string name;     // as in the folder: frame-000000.png, frame-000000.exr, frames.csv
    std::uintmax_t bytes = 0;
};

// What a movie writer writes into `folder` (frame-NNNNNN.png, frame-NNNNNN.exr, frames.csv): plain
// files only, in name order. Anything else in the folder (a temporary, a link, a subfolder, a file
// someone put there) is left out. Throws std::runtime_error if the folder cannot be read.
std::vector<MovieFile> movieFiles(const std::string& folder);

// What writeMovieZip returns when `write` refused the bytes.
inline const char* const kClientGone = "the client went away";

// Writes the zip of `files` (of `folder`) through `write`, each under "top/NAME". Returns "" once
// the whole archive went through, else why not (a file that vanished or changed size, or `write`
// returned false: kClientGone). A failure leaves the archive without its central
// directory, which no unzip takes for whole.
std::string writeMovieZip(const std::string& folder, const std::vector<MovieFile>& files, const std::string& top,
                          const std::function<bool(const char* data, std::size_t bytes)>& write);

} // namespace aurorawall::app::web
