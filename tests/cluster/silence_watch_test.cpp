// The master's deadline for silent ranks: a rank is silent only when its last heartbeat is older
// than the timeout (strictly), each heartbeat restarts its deadline, the master is never silent,
// and a finished rank is no longer watched. The hung-rank rule: a main thread without progress
// outside waits for longer than max(timeout, 4 x the master's slowest frame or own work this frame),
// only while the master waits, only in the frame loop and after a completed frame; and the
// main thread's progress record it is computed from.
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
        watch.heard(1, {RankPhase::Draw, static_cast<std::uint64_t>(t)}, t);
        watch.heard(2, {RankPhase::Draw, 7}, t < 10.0 ? t : 9.0); // rank 2 stops at 9 s
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
    watch.heard(1, {RankPhase::Finished, 3}, 0.5);
    watch.heard(1, {RankPhase::Gather, 3}, 0.6); // a late heartbeat does not revive it
    EXPECT_TRUE(watch.silentRanks(100.0).empty());
}

TEST(SilenceWatch, HeartbeatAgesCountFromEachRanksLastBeat)
{
    SilenceWatch watch(3, 10.0, 100.0);
    EXPECT_EQ(watch.heartbeatAgesS(100.0), (std::vector<double>{0.0, 0.0, 0.0}));
    watch.heard(1, {RankPhase::Draw, 4}, 101.25);
    const std::vector<double> ages = watch.heartbeatAgesS(102.0);
    ASSERT_EQ(ages.size(), 3u);
    EXPECT_EQ(ages[0], 0.0);          // the master, the watcher itself
    EXPECT_DOUBLE_EQ(ages[1], 0.75);  // since its beat
    EXPECT_DOUBLE_EQ(ages[2], 2.0);   // never heard: since the start
    EXPECT_EQ(watch.heartbeatAgesS(100.5)[1], 0.0); // a clock read before the beat: never negative
}

TEST(SilenceWatch, HeartbeatsFromUnknownRanksAreIgnored)
{
    SilenceWatch watch(2, 1.0, 0.0);
    watch.heard(5, {RankPhase::Draw, 1}, 0.5);
    watch.heard(-1, {RankPhase::Draw, 1}, 0.5);
    ASSERT_EQ(watch.silentRanks(2.0).size(), 1u);
}

TEST(RankPhase, DescriptionsNameTheFrame)
{
    EXPECT_EQ(describePhase(RankPhase::SetUp, 0), "set-up");
    EXPECT_EQ(describePhase(RankPhase::Draw, 12), "drawing frame 12");
    EXPECT_EQ(describePhase(RankPhase::Gather, 12), "the gather of frame 12");
}

namespace {

// The master's main thread waiting in the gather of frame 5, with frames of at most `slowestFrameS`.
MainThreadProgress::Snapshot masterWaiting(double slowestFrameS, double busyThisFrameS = 0.1)
{
    MainThreadProgress::Snapshot m;
    m.phase = RankPhase::Gather;
    m.frame = 5;
    m.waiting = true;
    m.slowestFrameS = slowestFrameS;
    m.busyThisFrameS = busyThisFrameS;
    return m;
}

} // namespace

TEST(HungRanks, AMainThreadWithoutProgressLongerThanTheTimeoutIsHung)
{
    SilenceWatch watch(4, 3.0, 0.0);
    watch.heard(1, {RankPhase::Gather, 5, true, 0.0}, 10.0);  // waiting for the master: fine
    watch.heard(2, {RankPhase::Draw, 5, false, 3.05}, 10.0);  // stuck in its draw
    watch.heard(3, {RankPhase::Draw, 5, false, 2.9}, 10.0);   // slow, within the timeout
    const std::vector<SilenceWatch::Hung> hung = watch.hungRanks(masterWaiting(0.2));
    EXPECT_DOUBLE_EQ(watch.stallLimitS(masterWaiting(0.2)), 3.0);
    ASSERT_EQ(hung.size(), 1u);
    EXPECT_EQ(hung[0].rank, 2);
    EXPECT_EQ(hung[0].beat.phase, RankPhase::Draw);
    EXPECT_EQ(hung[0].beat.frame, 5u);
    EXPECT_DOUBLE_EQ(hung[0].beat.stalledS, 3.05);
}

TEST(HungRanks, SlowFramesRaiseTheLimit)
{
    SilenceWatch watch(2, 3.0, 0.0);
    watch.heard(1, {RankPhase::Draw, 5, false, 7.0}, 10.0);
    // Frames of 2 s: the limit is 8 s; the master's own draw of 2.5 s this frame: 10 s.
    EXPECT_DOUBLE_EQ(watch.stallLimitS(masterWaiting(2.0)), 8.0);
    EXPECT_TRUE(watch.hungRanks(masterWaiting(2.0)).empty());
    EXPECT_DOUBLE_EQ(watch.stallLimitS(masterWaiting(1.0, 2.5)), 10.0);
    watch.heard(1, {RankPhase::Draw, 5, false, 9.0}, 11.0);
    EXPECT_EQ(watch.hungRanks(masterWaiting(2.0)).size(), 1u);
    EXPECT_TRUE(watch.hungRanks(masterWaiting(1.0, 2.5)).empty());
}

TEST(HungRanks, OnlyWhileTheMasterWaitsInTheFrameLoopAfterAFrame)
{
    SilenceWatch watch(2, 1.0, 0.0);
    watch.heard(1, {RankPhase::Draw, 5, false, 60.0}, 100.0);
    ASSERT_EQ(watch.hungRanks(masterWaiting(0.1)).size(), 1u);
    MainThreadProgress::Snapshot busy = masterWaiting(0.1);
    busy.waiting = false; // the master is at its own work: it is not waiting for rank 1 yet
    EXPECT_TRUE(watch.hungRanks(busy).empty());
    EXPECT_TRUE(watch.hungRanks(masterWaiting(0.0)).empty()); // no frame completed yet
    for (RankPhase outside : {RankPhase::SetUp, RankPhase::Output, RankPhase::Finished}) {
        SilenceWatch other(2, 1.0, 0.0);
        other.heard(1, {outside, 5, false, 60.0}, 100.0);
        EXPECT_TRUE(other.hungRanks(masterWaiting(0.1)).empty()) << describePhase(outside, 5);
    }
    SilenceWatch waiting(2, 1.0, 0.0);
    waiting.heard(1, {RankPhase::Draw, 5, true, 0.0}, 100.0); // in the exchange, waiting for another rank
    EXPECT_TRUE(waiting.hungRanks(masterWaiting(0.1)).empty());
}

TEST(MainThreadProgress, StallsCountOutsideWaitsAndFramesFromDrawToDraw)
{
    MainThreadProgress p(0.0);
    p.phaseChanged(RankPhase::SetUp, 0, 0.0);
    EXPECT_DOUBLE_EQ(p.at(2.0).stalledS, 2.0);
    p.phaseChanged(RankPhase::Draw, 0, 5.0);
    EXPECT_DOUBLE_EQ(p.at(5.5).slowestFrameS, 0.0); // no frame completed yet
    p.waitBegins(5.75);                            // the exchange
    MainThreadProgress::Snapshot s = p.at(9.0);
    EXPECT_TRUE(s.waiting);
    EXPECT_DOUBLE_EQ(s.stalledS, 0.0);
    EXPECT_DOUBLE_EQ(s.busyThisFrameS, 0.75);
    p.waitEnds(9.0);
    p.phaseChanged(RankPhase::Gather, 0, 9.5);
    s = p.at(9.5);
    EXPECT_DOUBLE_EQ(s.busyThisFrameS, 1.25); // 0.75 before the exchange, 0.5 after
    p.phaseChanged(RankPhase::Broadcast, 0, 9.5);
    p.waitBegins(9.5);
    p.waitEnds(10.0);
    p.phaseChanged(RankPhase::Draw, 1, 10.0); // frame 0 took 5 s
    p.phaseChanged(RankPhase::Draw, 2, 11.0); // frame 1 took 1 s
    s = p.at(14.0);
    EXPECT_DOUBLE_EQ(s.slowestFrameS, 5.0);
    EXPECT_DOUBLE_EQ(s.stalledS, 3.0);
    EXPECT_DOUBLE_EQ(s.busyThisFrameS, 3.0);
    EXPECT_EQ(s.phase, RankPhase::Draw);
    EXPECT_EQ(s.frame, 2u);
}
