// The master's deadline for silent ranks: a rank is silent only when its last heartbeat is older
// than the timeout (strictly), each heartbeat restarts its deadline, the master is never silent,
// and a finished rank is no longer watched.
#include "cluster/silence_watch.h"

#include <gtest/gtest.h>

using namespace aurorawall::cluster;

TEST(SilenceWatch, NoRankIsSilentBeforeTheTimeout)
{
    const SilenceWatch watch(3, 10.0, 100.0);
    EXPECT_TRUE(watch.silentRanks(100.0).empty());
    EXPECT_TRUE(watch.silentRanks(110.0).empty()); // exactly the timeout: not yet
}

TEST(SilenceWatch, RanksNeverHeardAfterSetUpAreSilentInSetUp)
{
    const SilenceWatch watch(3, 10.0, 100.0);
    const std::vector<SilenceWatch::Silent> silent = watch.silentRanks(110.5);
    ASSERT_EQ(silent.size(), 2u); // ranks 1 and 2, never rank 0
    EXPECT_EQ(silent[0].rank, 1);
    EXPECT_EQ(silent[1].rank, 2);
    EXPECT_EQ(silent[0].phase, RankPhase::SetUp);
    EXPECT_DOUBLE_EQ(silent[0].silentS, 10.5);
}

TEST(SilenceWatch, AHeartbeatRestartsTheDeadlineAndCarriesThePhase)
{
    SilenceWatch watch(3, 2.0, 0.0);
    // Rank 1 beats every 1.5 s (slower than half the timeout, faster than the timeout): never silent.
    for (double t = 1.5; t < 30.0; t += 1.5) {
        watch.heard(1, RankPhase::Draw, static_cast<std::uint64_t>(t), t);
        watch.heard(2, RankPhase::Draw, 7, t < 10.0 ? t : 9.0); // rank 2 stops at 9 s
        const std::vector<SilenceWatch::Silent> silent = watch.silentRanks(t + 0.4);
        if (t + 0.4 - 9.0 > 2.0) {
            ASSERT_EQ(silent.size(), 1u) << "at " << t;
            EXPECT_EQ(silent[0].rank, 2);
            EXPECT_EQ(silent[0].phase, RankPhase::Draw);
            EXPECT_EQ(silent[0].frame, 7u);
            EXPECT_DOUBLE_EQ(silent[0].silentS, t + 0.4 - 9.0);
        } else {
            EXPECT_TRUE(silent.empty()) << "at " << t;
        }
    }
}

TEST(SilenceWatch, AFinishedRankIsNoLongerWatched)
{
    SilenceWatch watch(2, 1.0, 0.0);
    watch.heard(1, RankPhase::Finished, 3, 0.5);
    watch.heard(1, RankPhase::Gather, 3, 0.6); // a late heartbeat does not revive it
    EXPECT_TRUE(watch.silentRanks(100.0).empty());
}

TEST(SilenceWatch, HeartbeatsFromUnknownRanksAreIgnored)
{
    SilenceWatch watch(2, 1.0, 0.0);
    watch.heard(5, RankPhase::Draw, 1, 0.5);
    watch.heard(-1, RankPhase::Draw, 1, 0.5);
    ASSERT_EQ(watch.silentRanks(2.0).size(), 1u);
}

TEST(RankPhase, DescriptionsNameTheFrame)
{
    EXPECT_EQ(describePhase(RankPhase::SetUp, 0), "set-up");
    EXPECT_EQ(describePhase(RankPhase::Draw, 12), "drawing frame 12");
    EXPECT_EQ(describePhase(RankPhase::Gather, 12), "the gather of frame 12");
}
