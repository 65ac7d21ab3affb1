#include "io/jpeg.h"
#include "temp_dir.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <vector>

#include <jpeglib.h>

using namespace aurorawall::io;
using aurorawall::io::test::TempDir;

namespace {

// A colour JPEG of w x h pixels, encoded by libjpeg at quality 100: a horizontal ramp of red.
std::vector<unsigned char> encodeRamp(int w, int h)
{
    jpeg_compress_struct info;
    jpeg_error_mgr errors;
    info.err = jpeg_std_error(&errors);
    jpeg_create_compress(&info);
    unsigned char* buffer = nullptr;
    unsigned long size = 0;
    jpeg_mem_dest(&info, &buffer, &size);
    info.image_width = static_cast<JDIMENSION>(w);
    info.image_height = static_cast<JDIMENSION>(h);
    info.input_components = 3;
    info.in_color_space = JCS_RGB;
    jpeg_set_defaults(&info);
    jpeg_set_quality(&info, 100, TRUE);
    jpeg_start_compress(&info, TRUE);
    std::vector<unsigned char> row(3 * static_cast<size_t>(w));
    for (int x = 0; x < w; ++x) {
        row[3 * x] = static_cast<unsigned char>(x * 255 / (w - 1));
        row[3 * x + 1] = 64;
        row[3 * x + 2] = 128;
    }
    while (info.next_scanline < info.image_height) {
        JSAMPROW rows[1] = {row.data()};
        jpeg_write_scanlines(&info, rows, 1);
    }
    jpeg_finish_compress(&info);
    std::vector<unsigned char> bytes(buffer, buffer + size);
    jpeg_destroy_compress(&info);
    std::free(buffer);
    return bytes;
}

void writeBytes(const std::string& path, const std::vector<unsigned char>& bytes)
{
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

// The message readJpeg throws for `path`, and what it printed on stderr meanwhile.
std::pair<std::string, std::string> failureOf(const std::string& path)
{
    testing::internal::CaptureStderr();
    std::string message;
    try {
        readJpeg(path);
    } catch (const std::runtime_error& e) {
        message = e.what();
    }
    return {message, testing::internal::GetCapturedStderr()};
}

} // namespace

TEST(Jpeg, DecodesTheEncodedSrgbValuesTopDown)
{
    TempDir dir;
    writeBytes(dir.file("ramp.jpg"), encodeRamp(64, 16));
    const Image image = readJpeg(dir.file("ramp.jpg"));
    ASSERT_EQ(image.width, 64);
    ASSERT_EQ(image.height, 16);
    // Quality 100 with 2x2 chroma subsampling: a smooth ramp comes back within a few levels of 255.
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const float* p = image.pixel(x, y);
            EXPECT_NEAR(p[0], x / 63.0f, 4.0f / 255) << x << "," << y;
            EXPECT_NEAR(p[1], 64 / 255.0f, 4.0f / 255) << x << "," << y;
            EXPECT_NEAR(p[2], 128 / 255.0f, 4.0f / 255) << x << "," << y;
            EXPECT_EQ(p[3], 1.0f);
        }
}

// libjpeg decodes a truncated file partly and only warns; the reader refuses it, naming the file, and
// libjpeg prints nothing of its own.
TEST(Jpeg, RefusesTruncatedDataWithOneMessageNamingTheFile)
{
    TempDir dir;
    std::vector<unsigned char> bytes = encodeRamp(64, 64);
    bytes.resize(bytes.size() * 8 / 10);
    writeBytes(dir.file("cut.jpg"), bytes);
    const auto [message, printed] = failureOf(dir.file("cut.jpg"));
    EXPECT_NE(message.find(dir.file("cut.jpg") + ": "), std::string::npos) << message;
    EXPECT_EQ(printed, "");
}

// A header that claims more than kMaxJpegSide pixels on a side is refused before any pixel is
// allocated (65500 x 65500 RGBA floats would be 64 GiB).
TEST(Jpeg, RefusesAnImageLargerThanAnyTexture)
{
    TempDir dir;
    std::vector<unsigned char> bytes = encodeRamp(16, 16);
    // The baseline frame header (0xFF 0xC0): length (2 bytes), precision (1), height (2), width (2).
    std::size_t sof = 0;
    while (sof + 1 < bytes.size() && !(bytes[sof] == 0xFF && bytes[sof + 1] == 0xC0))
        ++sof;
    ASSERT_LT(sof + 9, bytes.size()) << "no baseline frame header";
    for (std::size_t i : {sof + 5, sof + 7}) {
        bytes[i] = 0xFF; // 65500 = 0xFFDC
        bytes[i + 1] = 0xDC;
    }
    writeBytes(dir.file("huge.jpg"), bytes);
    const auto [message, printed] = failureOf(dir.file("huge.jpg"));
    EXPECT_NE(message.find("huge.jpg: 65500 x 65500 pixels, more than 16384 on a side"), std::string::npos) << message;
    EXPECT_EQ(printed, "");
}

TEST(Jpeg, RefusesAMissingFile)
{
    TempDir dir;
    const auto [message, printed] = failureOf(dir.file("none.jpg"));
    EXPECT_EQ(message, dir.file("none.jpg") + ": cannot open");
}
