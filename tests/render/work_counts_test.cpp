// The work summary of render/work_counts.h: the mean per pixel and the mean of each 8x4 block's
// largest count, on hand-made counts.
#include "render/work_counts.h"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace aurorawall::render;

TEST(WorkCounts, MeanPerPixelAndMeanOfEachBlocksLargest)
{
    // 16x4 pixels: two blocks. One pixel of the left block does 32 steps, the others 1; the right
    // block does 2 everywhere. Quantity 1 is 0 everywhere; 2 and 3 equal 0.
    const glm::ivec2 size(16, 4);
    std::vector<float> counts(16 * 4 * kWorkQuantities, 0.0f);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 16; ++x)
            counts[(y * 16 + x) * kWorkQuantities] = x < 8 ? 1.0f : 2.0f;
    counts[(2 * 16 + 3) * kWorkQuantities] = 32.0f;
    const WorkSummary s = summarizeWork(counts, size);
    EXPECT_DOUBLE_EQ(s.meanPerPixel[0], (31.0 * 1.0 + 32.0 + 32.0 * 2.0) / 64.0);
    EXPECT_DOUBLE_EQ(s.meanBlockMax[0], (32.0 + 2.0) / 2.0);
    EXPECT_DOUBLE_EQ(s.meanPerPixel[1], 0.0);
    EXPECT_DOUBLE_EQ(s.meanBlockMax[3], 0.0);
}

TEST(WorkCounts, PartialBlocksAtTheEdgesCount)
{
    // 9x5 pixels: 2x2 blocks, three of them partial; the lone pixel (8, 4) does 5 fetches.
    const glm::ivec2 size(9, 5);
    std::vector<float> counts(9 * 5 * kWorkQuantities, 0.0f);
    counts[(4 * 9 + 8) * kWorkQuantities + 3] = 5.0f;
    const WorkSummary s = summarizeWork(counts, size);
    EXPECT_DOUBLE_EQ(s.meanPerPixel[3], 5.0 / 45.0);
    EXPECT_DOUBLE_EQ(s.meanBlockMax[3], 5.0 / 4.0);
    EXPECT_THROW(summarizeWork(std::vector<float>(3), size), std::invalid_argument);
}
