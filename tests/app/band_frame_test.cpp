#include "app/band_frame.h"
#include "io/band_compression.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

using namespace aurorawall;

namespace {

// Band 12 of a wall: screen 5, rows 16-23 of a 40-pixel-wide screen, owned by rank 2.
const cluster::Band kBand{5, 16, 8, 2};
constexpr int kWidth = 40;

std::vector<std::uint16_t> bandHalves()
{
    std::vector<std::uint16_t> halves(3 * kWidth * kBand.height);
    for (size_t i = 0; i < halves.size(); ++i)
        halves[i] = static_cast<std::uint16_t>(0x3c00 + i % 37);
    return halves;
}

std::string errorOf(const std::vector<std::uint8_t>& bytes)
{
    try {
        app::receivedBandPixels(bytes, kBand, 12, kWidth, 2, 7);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(BandFrame, ReceivedBandPixelsAreTheSentHalves)
{
    const std::vector<std::uint16_t> sent = bandHalves();
    EXPECT_EQ(app::receivedBandPixels(io::compressHalves(sent, 3), kBand, 12, kWidth, 2, 7), sent);
}

// A short, corrupt or other band's block is one line naming the receiving rank, the band and the sender.
TEST(BandFrame, BadBlockIsOneLineNamingRankAndBand)
{
    const std::vector<std::uint8_t> good = io::compressHalves(bandHalves(), 3);
    const std::string prefix = "rank 2: band 12 (screen 5, rows 16-23) from rank 7: ";
    const std::vector<std::vector<std::uint8_t>> bad = {
        {good.begin(), good.begin() + static_cast<long>(good.size() / 2)},
        {},
        std::vector<std::uint8_t>(good.size(), 0xa5),
        io::compressHalves(std::vector<std::uint16_t>(3 * kWidth * 9, 0), 3),
    };
    for (const auto& bytes : bad) {
        const std::string error = errorOf(bytes);
        EXPECT_EQ(error.rfind(prefix, 0), 0u) << error;
        EXPECT_GT(error.size(), prefix.size()) << error;
        EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    }
}
