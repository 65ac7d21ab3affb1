#include "cluster/rank_groups.h"

#include <gtest/gtest.h>

namespace aurorawall::cluster {
namespace {

TEST(RankGroups, OneValueForAllRanks)
{
    EXPECT_EQ(ranksByValue({"NVIDIA H100"}), "NVIDIA H100 (rank 0)");
    EXPECT_EQ(ranksByValue({"gpu", "gpu", "gpu", "gpu"}), "gpu (ranks 0-3)");
}

TEST(RankGroups, ValuesInTheOrderOfTheirFirstRankWithRunsOfRanks)
{
    EXPECT_EQ(ranksByValue({"A", "A", "A", "B", "B", "A"}), "A (ranks 0-2, 5); B (ranks 3-4)");
    EXPECT_EQ(ranksByValue({"llvmpipe", "gpu", "llvmpipe", "gpu", "gpu"}),
              "llvmpipe (ranks 0, 2); gpu (ranks 1, 3-4)");
}

TEST(RankGroups, NoRanksNoLine)
{
    EXPECT_EQ(ranksByValue({}), "");
}

} // namespace
} // namespace aurorawall::cluster
