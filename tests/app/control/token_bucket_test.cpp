// The rate limit of the control port: a burst at once, then the rate, never more than the burst
// saved up, and a clock that steps back gives nothing.
#include "app/control/token_bucket.h"

#include <gtest/gtest.h>

using aurorawall::app::control::TokenBucket;

namespace {

// How many of `count` lines at time nowS the bucket lets through.
int taken(TokenBucket& bucket, int count, double nowS)
{
    int n = 0;
    for (int i = 0; i < count; ++i)
        n += bucket.take(nowS) ? 1 : 0;
    return n;
}

} // namespace

TEST(TokenBucket, ABurstAtOnceThenNothingUntilItRefills)
{
    TokenBucket bucket(100.0, 100.0, 10.0);
    EXPECT_EQ(taken(bucket, 150, 10.0), 100);
    EXPECT_FALSE(bucket.take(10.0));
    EXPECT_FALSE(bucket.take(10.009)); // 0.9 of a token
    EXPECT_TRUE(bucket.take(10.011));  // 1.1
    EXPECT_FALSE(bucket.take(10.011));
}

TEST(TokenBucket, TheRateIsKeptOverAnyLength)
{
    // 10,000 lines a second for 10 s against 100 per second: the burst plus the rate times the time.
    TokenBucket bucket(100.0, 100.0, 0.0);
    int n = 0;
    for (int ms = 0; ms < 10000; ++ms)
        n += taken(bucket, 10, ms * 1e-3);
    EXPECT_EQ(n, 100 + 999);
}

TEST(TokenBucket, NeverSavesMoreThanTheBurst)
{
    TokenBucket bucket(100.0, 20.0, 0.0);
    EXPECT_EQ(taken(bucket, 20, 0.0), 20);
    EXPECT_EQ(taken(bucket, 1000, 3600.0), 20); // an hour idle saves up only the burst
}

TEST(TokenBucket, AClockSteppingBackGivesNothing)
{
    TokenBucket bucket(100.0, 10.0, 5.0);
    EXPECT_EQ(taken(bucket, 10, 5.0), 10);
    EXPECT_FALSE(bucket.take(1.0));
    EXPECT_FALSE(bucket.take(5.0)); // back at the time it had reached: still nothing
    EXPECT_TRUE(bucket.take(5.1));
}
