#include "io/exr.h"

#include "io/atomic_file.h"
#include "io/half_pixels.h"

#include <ImfHeader.h>
#include <ImfRgbaFile.h>
#include <ImfStdIO.h>
#include <half.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace aurorawall::io {

namespace {

// The documented clamping of io/half_pixels.h.
half toHalf(float value)
{
    half h;
    h.setBits(halfBits(value));
    return h;
}

void writeTemporaryExr(const std::string& temporaryPath, const Image& image, ExrChannels channels)
{
    std::vector<Imf::Rgba> pixels(std::size_t(image.width) * image.height);
    for (std::size_t i = 0; i < pixels.size(); ++i) {
        const float* p = &image.rgba[4 * i];
        pixels[i] = Imf::Rgba(toHalf(p[0]), toHalf(p[1]), toHalf(p[2]), toHalf(p[3]));
    }
    Imf::Header header(image.width, image.height);
    header.compression() = Imf::ZIP_COMPRESSION;

    // Our own stream, so that errors while the file is finished in ~RgbaOutputFile
    // (which swallows them) still show in the stream state checked below.
    std::ofstream file(temporaryPath, std::ios::binary | std::ios::trunc);
    if (!file)
        throw std::runtime_error(temporaryPath + ": cannot create file (" + std::strerror(errno) + ")");
    {
        Imf::StdOFStream stream(file, temporaryPath.c_str());
        Imf::RgbaOutputFile output(stream, header,
                                   channels == ExrChannels::RGBA ? Imf::WRITE_RGBA : Imf::WRITE_RGB);
        output.setFrameBuffer(pixels.data(), 1, image.width);
        output.writePixels(image.height);
    }
    file.close();
    if (!file)
        throw std::runtime_error(temporaryPath + ": write failed (" + std::strerror(errno) + ")");
}

} // namespace

void writeExr(const std::string& path, const Image& image, ExrChannels channels)
{
    checkImage(image);
    if (image.width == 0 || image.height == 0)
        throw std::invalid_argument(path + ": cannot write an empty image as EXR");
    try {
        writeFileAtomically(path, [&](const std::string& temporary) {
            writeTemporaryExr(temporary, image, channels);
        });
    } catch (const std::exception& e) {
        // OpenEXR's exceptions (Iex::BaseExc) derive from std::exception only.
        throw std::runtime_error(path + ": cannot write EXR: " + e.what());
    }
}

Image readExr(const std::string& path)
{
    try {
        Imf::RgbaInputFile input(path.c_str());
        const Imath::Box2i window = input.dataWindow();
        const int width = window.max.x - window.min.x + 1;
        const int height = window.max.y - window.min.y + 1;
        std::vector<Imf::Rgba> pixels(std::size_t(width) * height);
        // The frame buffer is addressed in data-window coordinates, so shift its base.
        input.setFrameBuffer(pixels.data() - window.min.x - std::ptrdiff_t(window.min.y) * width, 1, width);
        input.readPixels(window.min.y, window.max.y);

        Image image(width, height);
        for (std::size_t i = 0; i < pixels.size(); ++i) {
            float* p = &image.rgba[4 * i];
            p[0] = pixels[i].r;
            p[1] = pixels[i].g;
            p[2] = pixels[i].b;
            p[3] = pixels[i].a;
        }
        return image;
    } catch (const std::exception& e) {
        throw std::runtime_error(path + ": cannot read EXR: " + e.what());
    }
}

} // namespace aurorawall::io
