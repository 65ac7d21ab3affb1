#include "io/jpeg.h"

#include <cstdio>
#include <csetjmp>
#include <memory>
#include <stdexcept>

#include <jpeglib.h>

namespace aurorawall::io {

namespace {

// libjpeg reports fatal errors through error_exit; jump back out instead of exiting.
struct ErrorManager {
    jpeg_error_mgr base;
    std::jmp_buf jump;
    char message[JMSG_LENGTH_MAX];
};

void onError(j_common_ptr info)
{
    auto* errors = reinterpret_cast<ErrorManager*>(info->err);
    (*info->err->format_message)(info, errors->message);
    std::longjmp(errors->jump, 1);
}

// A warning (level −1: corrupt or truncated data, which libjpeg would decode partly) is an error too;
// trace messages (levels ≥ 0) are dropped, so libjpeg prints nothing of its own.
void onMessage(j_common_ptr info, int level)
{
    if (level < 0)
        onError(info);
}

} // namespace

Image readJpeg(const std::string& path)
{
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!file)
        throw std::runtime_error(path + ": cannot open");
    jpeg_decompress_struct info;
    ErrorManager errors;
    info.err = jpeg_std_error(&errors.base);
    errors.base.error_exit = onError;
    errors.base.emit_message = onMessage;
    // No C++ object may be constructed between a setjmp and a longjmp to it, so the image and
    // the row buffer are made between two setjmp calls.
    Image image;
    std::vector<unsigned char> row;
    if (setjmp(errors.jump)) {
        jpeg_destroy_decompress(&info);
        throw std::runtime_error(path + ": " + errors.message);
    }
    jpeg_create_decompress(&info);
    jpeg_stdio_src(&info, file.get());
    jpeg_read_header(&info, TRUE);
    info.out_color_space = JCS_RGB;
    if (info.image_width > kMaxJpegSide || info.image_height > kMaxJpegSide) {
        jpeg_destroy_decompress(&info);
        throw std::runtime_error(path + ": " + std::to_string(info.image_width) + " x " +
                                 std::to_string(info.image_height) + " pixels, more than " +
                                 std::to_string(kMaxJpegSide) + " on a side");
    }
    jpeg_start_decompress(&info);
    image = Image(static_cast<int>(info.output_width), static_cast<int>(info.output_height));
    row.resize(3 * static_cast<size_t>(info.output_width));
    if (setjmp(errors.jump)) {
        jpeg_destroy_decompress(&info);
        throw std::runtime_error(path + ": " + errors.message);
    }
    while (info.output_scanline < info.output_height) {
        const int y = static_cast<int>(info.output_scanline);
        JSAMPROW rows[1] = {row.data()};
        jpeg_read_scanlines(&info, rows, 1);
        for (int x = 0; x < image.width; ++x) {
            float* p = image.pixel(x, y);
            for (int c = 0; c < 3; ++c)
                p[c] = row[3 * size_t(x) + c] / 255.0f;
            p[3] = 1.0f;
        }
    }
    jpeg_finish_decompress(&info);
    jpeg_destroy_decompress(&info);
    return image;
}

} // namespace aurorawall::io
