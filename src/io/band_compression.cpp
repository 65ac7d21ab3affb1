#include "io/band_compression.h"

#include <zstd.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

namespace aurorawall::io {

namespace {

// Zstandard's fastest standard level (1); the frame carries a checksum of its content (XXH64,
// 4 bytes), so a corrupt block is an error and never wrong pixels.
constexpr int kZstdLevel = 1;

// Plane order: for each channel, that channel's halves in pixel order. Half k of plane c is
// halves[channels * k + c]; the byte planes hold the high bytes of all differences, then the low.
std::vector<std::uint8_t> bytePlanes(const std::vector<std::uint16_t>& halves, int channels)
{
    const std::size_t n = halves.size();
    std::vector<std::uint8_t> planes(2 * n);
    std::size_t out = 0;
    for (int c = 0; c < channels; ++c) {
        std::uint16_t previous = 0;
        for (std::size_t i = static_cast<std::size_t>(c); i < n; i += static_cast<std::size_t>(channels)) {
            const auto delta = static_cast<std::uint16_t>(halves[i] - previous);
            previous = halves[i];
            planes[out] = static_cast<std::uint8_t>(delta >> 8);
            planes[n + out] = static_cast<std::uint8_t>(delta & 0xff);
            ++out;
        }
    }
    return planes;
}

std::vector<std::uint16_t> halvesFromPlanes(const std::vector<std::uint8_t>& planes, int channels)
{
    const std::size_t n = planes.size() / 2;
    std::vector<std::uint16_t> halves(n);
    std::size_t in = 0;
    for (int c = 0; c < channels; ++c) {
        std::uint16_t previous = 0;
        for (std::size_t i = static_cast<std::size_t>(c); i < n; i += static_cast<std::size_t>(channels)) {
            const auto delta = static_cast<std::uint16_t>((planes[in] << 8) | planes[n + in]);
            previous = static_cast<std::uint16_t>(previous + delta);
            halves[i] = previous;
            ++in;
        }
    }
    return halves;
}

void checkChannels(int channels)
{
    if (channels < 1)
        throw std::invalid_argument("half compression: channels must be at least 1, not " + std::to_string(channels));
}

} // namespace

std::vector<std::uint8_t> compressHalves(const std::vector<std::uint16_t>& halves, int channels)
{
    checkChannels(channels);
    const std::vector<std::uint8_t> planes = bytePlanes(halves, channels);
    const std::unique_ptr<ZSTD_CCtx, decltype(&ZSTD_freeCCtx)> context(ZSTD_createCCtx(), &ZSTD_freeCCtx);
    if (!context)
        throw std::runtime_error("half compression: no memory for a compression context");
    for (const auto& [parameter, value] : {std::pair{ZSTD_c_compressionLevel, kZstdLevel}, std::pair{ZSTD_c_checksumFlag, 1}})
        if (const std::size_t status = ZSTD_CCtx_setParameter(context.get(), parameter, value); ZSTD_isError(status))
            throw std::runtime_error(std::string("half compression: ") + ZSTD_getErrorName(status));
    std::vector<std::uint8_t> compressed(ZSTD_compressBound(planes.size()));
    const std::size_t size =
        ZSTD_compress2(context.get(), compressed.data(), compressed.size(), planes.data(), planes.size());
    if (ZSTD_isError(size))
        throw std::runtime_error(std::string("half compression: ") + ZSTD_getErrorName(size));
    compressed.resize(size);
    return compressed;
}

std::vector<std::uint16_t> decompressHalves(const std::vector<std::uint8_t>& compressed, std::size_t count,
                                            int channels)
{
    checkChannels(channels);
    const unsigned long long content = ZSTD_getFrameContentSize(compressed.data(), compressed.size());
    if (content == ZSTD_CONTENTSIZE_ERROR || content == ZSTD_CONTENTSIZE_UNKNOWN)
        throw std::runtime_error("half compression: not a compressed block of halves (" + std::to_string(compressed.size()) + " bytes)");
    if (ZSTD_findFrameCompressedSize(compressed.data(), compressed.size()) != compressed.size())
        throw std::runtime_error("half compression: " + std::to_string(compressed.size()) +
                                 " bytes are not exactly one compressed block");
    if (content != 2 * count)
        throw std::runtime_error("half compression: the block holds " + std::to_string(content / 2) + " halves, expected " + std::to_string(count));
    std::vector<std::uint8_t> planes(2 * count);
    const std::size_t size = ZSTD_decompress(planes.data(), planes.size(), compressed.data(), compressed.size());
    if (ZSTD_isError(size))
        throw std::runtime_error(std::string("half compression: corrupt block: ") + ZSTD_getErrorName(size));
    if (size != planes.size())
        throw std::runtime_error("half compression: truncated block: " + std::to_string(size / 2) + " of " +
                                 std::to_string(count));
    return halvesFromPlanes(planes, channels);
}

} // namespace aurorawall::io
