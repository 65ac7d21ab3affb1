#include "io/band_compression.h"
#include "io/half_pixels.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

using namespace aurorawall::io;

namespace {

void expectRoundTrip(const std::vector<std::uint16_t>& halves, int channels)
{
    EXPECT_EQ(decompressHalves(compressHalves(halves, channels), halves.size(), channels), halves);
}

std::vector<std::uint16_t> randomHalves(std::size_t count, unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_int_distribution<unsigned> bits(0, 0xffff);
    std::vector<std::uint16_t> halves(count);
    for (auto& h : halves)
        h = static_cast<std::uint16_t>(bits(random));
    return halves;
}

// A dark sky: small positive halves drifting slowly along the row, as rendered bands are.
std::vector<std::uint16_t> darkSky(std::size_t pixels)
{
    std::vector<std::uint16_t> halves;
    for (std::size_t i = 0; i < pixels; ++i)
        for (int c = 0; c < 3; ++c)
            halves.push_back(halfBits(1e-4f * float(1 + c) * (1.0f + 0.001f * float(i % 997))));
    return halves;
}

} // namespace

// Every bit pattern (NaN and infinity patterns included) comes back unchanged, for any length.
TEST(BandCompression, RandomHalvesRoundTripBitExact)
{
    for (std::size_t count : {std::size_t(0), std::size_t(1), std::size_t(2), std::size_t(3), std::size_t(7),
                              std::size_t(3 * 168 * 13), std::size_t(3 * 1680 * 263 + 1)})
        for (int channels : {1, 3})
            expectRoundTrip(randomHalves(count, static_cast<unsigned>(count)), channels);
}

TEST(BandCompression, AllZeroRoundTripsAndShrinks)
{
    const std::vector<std::uint16_t> zeros(3 * 1680 * 263, 0);
    expectRoundTrip(zeros, 3);
    EXPECT_LT(compressHalves(zeros, 3).size(), zeros.size() * 2 / 1000);
}

// The halves a rendered pixel can be after io/half_pixels.h's clamp: +-0, the smallest subnormal,
// the smallest normal, 1, +-65504 (HALF_MAX), in every order; an odd count leaves the planes uneven.
TEST(BandCompression, ExtremesRoundTripBitExact)
{
    const std::vector<std::uint16_t> extremes = {0x0000, 0x8000, 0x0001, 0x8001, 0x0400, 0x3c00,
                                                 0x7bff, 0xfbff, 0x03ff, 0x7bfe, 0x0000};
    expectRoundTrip(extremes, 3);
    std::vector<std::uint16_t> repeated;
    for (int i = 0; i < 5001; ++i)
        repeated.push_back(extremes[static_cast<std::size_t>(i * 7) % extremes.size()]);
    expectRoundTrip(repeated, 3);
    EXPECT_EQ(halfBits(65504.0f), 0x7bff);
    EXPECT_EQ(halfBits(-1e9f), 0xfbff);
}

// Smooth dark sky is what the transform is for: at least 4 to 1 on this synthetic band.
TEST(BandCompression, DarkSkyCompresses)
{
    const std::vector<std::uint16_t> sky = darkSky(1680 * 263);
    expectRoundTrip(sky, 3);
    EXPECT_LT(compressHalves(sky, 3).size() * 4, sky.size() * 2);
}

TEST(BandCompression, CorruptOrShortBlocksAreErrors)
{
    const std::vector<std::uint16_t> sky = darkSky(168 * 13);
    const std::vector<std::uint8_t> good = compressHalves(sky, 3);

    std::vector<std::uint8_t> truncated(good.begin(), good.begin() + static_cast<long>(good.size() / 2));
    EXPECT_THROW(decompressHalves(truncated, sky.size(), 3), std::runtime_error);
    EXPECT_THROW(decompressHalves({}, sky.size(), 3), std::runtime_error);
    EXPECT_THROW(decompressHalves(good, sky.size() + 3, 3), std::runtime_error);
    EXPECT_THROW(decompressHalves(std::vector<std::uint8_t>(good.size(), 0xa5), sky.size(), 3), std::runtime_error);
    // A good block with anything after it (here a second copy) is not one block.
    std::vector<std::uint8_t> trailing = good;
    trailing.insert(trailing.end(), good.begin(), good.end());
    EXPECT_THROW(decompressHalves(trailing, sky.size(), 3), std::runtime_error);
    // A flipped byte never gives other pixels: it is caught (the frame's header or the content
    // checksum), or it lay in bits the decoder does not read and the halves come back unchanged.
    int caught = 0;
    for (std::size_t i = 0; i < good.size(); ++i) {
        std::vector<std::uint8_t> corrupt = good;
        corrupt[i] ^= 0x5a;
        try {
            EXPECT_EQ(decompressHalves(corrupt, sky.size(), 3), sky) << "byte " << i;
        } catch (const std::runtime_error&) {
            ++caught;
        }
    }
    // Most flips are caught outright: the frame header, the block headers and the checksum cover
    // nearly every byte (measured: 395 of the 397 bytes of this block).
    EXPECT_GT(caught, static_cast<int>(good.size()) * 9 / 10);
}
