// The master clock: the animation time of every frame, exact in double, through pause, play, speed,
// single steps and jumps; the camera along its straight or keyed path; the frame count.
#include "cluster/master_clock.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

using namespace aurorawall;
using namespace aurorawall::cluster;

namespace {

ClockSettings fixedStep(double startS, double stepS, std::uint64_t frames = 0)
{
    ClockSettings s;
    s.frames = frames;
    s.startTimeS = startS;
    s.timeStepS = stepS;
    return s;
}

scene::Camera flyingCamera()
{
    scene::Camera c;
    c.positionKm = {0.0, 0.0, 6441.0};
    c.forward = {0.0, 1.0, 0.0};
    c.up = {0.0, 0.0, 1.0};
    c.speedKmPerS = 2.5;
    return c;
}

} // namespace

TEST(MasterClock, FrameNShowsStartPlusNSteps)
{
    // The product start + n dt, not a running sum: 0.1 added 1000 times is not 100.
    MasterClock clock(fixedStep(7.0, 0.1, 1000), flyingCamera(), 1.0);
    for (std::uint64_t n = 0; n < 1000; ++n) {
        const FrameState s = clock.next(false);
        ASSERT_EQ(s.frame, n);
        ASSERT_EQ(s.timeS, 7.0 + static_cast<double>(n) * 0.1);
        ASSERT_EQ(s.quit, 0);
    }
    EXPECT_EQ(clock.next(false).quit, 1);
}

TEST(MasterClock, StopRequestedQuits)
{
    MasterClock clock(fixedStep(0.0, 1.0), flyingCamera(), 1.0);
    EXPECT_EQ(clock.next(false).quit, 0);
    EXPECT_EQ(clock.next(true).quit, 1);
}

TEST(MasterClock, PauseHoldsTheTimeAndStepAdvancesOneFrame)
{
    MasterClock clock(fixedStep(0.0, 0.25), flyingCamera(), 1.0);
    clock.next(false);
    clock.next(false); // t = 0.25
    clock.pause();
    EXPECT_TRUE(clock.paused());
    EXPECT_EQ(clock.next(false).timeS, 0.25);
    EXPECT_EQ(clock.next(false).timeS, 0.25);
    clock.step();
    EXPECT_EQ(clock.next(false).timeS, 0.5);
    EXPECT_EQ(clock.next(false).timeS, 0.5);
    clock.step();
    clock.step(); // two steps before one frame: two frames' time
    EXPECT_EQ(clock.next(false).timeS, 1.0);
    clock.play();
    EXPECT_EQ(clock.next(false).timeS, 1.25);
    EXPECT_EQ(clock.next(false).timeS, 1.5);
    clock.step(); // playing: no effect
    EXPECT_EQ(clock.next(false).timeS, 1.75);
}

TEST(MasterClock, SpeedScalesTheStepFromNowOn)
{
    MasterClock clock(fixedStep(0.0, 0.5), flyingCamera(), 1.0);
    clock.next(false);
    clock.next(false); // t = 0.5
    clock.setSpeed(4.0);
    EXPECT_EQ(clock.speed(), 4.0);
    for (int n = 1; n <= 10; ++n)
        EXPECT_EQ(clock.next(false).timeS, 0.5 + n * 2.0);
    clock.setSpeed(0.1);
    for (int n = 1; n <= 10; ++n)
        EXPECT_EQ(clock.next(false).timeS, 20.5 + n * (0.1 * 0.5));
    clock.pause();
    clock.step();
    EXPECT_EQ(clock.next(false).timeS, 21.0 + 0.1 * 0.5);
}

TEST(MasterClock, SetTimeIsShownExactlyByTheNextFrame)
{
    MasterClock clock(fixedStep(0.0, 0.5), flyingCamera(), 1.0);
    clock.next(false);
    clock.setTime(120.0);
    EXPECT_EQ(clock.timeS(), 120.0); // status answers with it before it is drawn
    EXPECT_EQ(clock.next(false).timeS, 120.0);
    EXPECT_EQ(clock.next(false).timeS, 120.5);
    clock.pause();
    clock.setTime(-3.0);
    EXPECT_EQ(clock.next(false).timeS, -3.0);
    EXPECT_EQ(clock.next(false).timeS, -3.0);
    clock.setTime(10.0);
    clock.step(); // a step after a jump counts from the time jumped to
    EXPECT_EQ(clock.next(false).timeS, 10.5);
    // Frame numbers keep counting through it all.
    EXPECT_EQ(clock.next(false).frame, 6u);
}

TEST(MasterClock, TheCameraFliesWithAnimationTime)
{
    const scene::Camera start = flyingCamera();
    MasterClock clock(fixedStep(100.0, 1.0), start, 1.0);
    const FrameState first = clock.next(false);
    EXPECT_EQ(first.cameraPositionKm, start.positionKm);
    EXPECT_EQ(first.cameraBack, -start.forward);
    EXPECT_EQ(first.cameraRight, glm::cross(start.forward, start.up));
    clock.setTime(140.0); // 40 s later along its path: 100 km north of its start along +y
    EXPECT_EQ(clock.next(false).cameraPositionKm, start.positionKm + glm::dvec3(0.0, 100.0, 0.0));
    // Put somewhere else, it flies on from there.
    scene::Camera moved = start;
    moved.positionKm = {6500.0, 0.0, 0.0};
    moved.forward = {0.0, 0.0, 1.0};
    moved.up = {1.0, 0.0, 0.0};
    clock.setCamera(moved);
    EXPECT_EQ(clock.camera().positionKm, moved.positionKm);
    clock.next(false); // t = 141
    const FrameState later = clock.next(false); // t = 142
    EXPECT_EQ(later.timeS, 142.0);
    EXPECT_EQ(later.cameraPositionKm, glm::dvec3(6500.0, 0.0, 5.0));
    EXPECT_EQ(later.cameraBack, glm::dvec3(0.0, 0.0, -1.0));
}

TEST(MasterClock, TheCameraFollowsItsKeyedPathUntilPutElsewhere)
{
    // Two keys 10 s apart on a straight line at 10 km/s: the path is that line, held after 10 s.
    const scene::CameraFrame frame{{0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}};
    const glm::dquat q = scene::orientationOf(frame);
    scene::Camera c;
    c.path = scene::CameraPath({{0.0, {0.0, 0.0, 6441.0}, q}, {10.0, {0.0, 100.0, 6441.0}, q}});
    MasterClock clock(fixedStep(0.0, 0.5), c, 1.0);
    clock.setTime(2.5);
    const FrameState s = clock.next(false);
    EXPECT_NEAR(glm::length(s.cameraPositionKm - glm::dvec3(0.0, 25.0, 6441.0)), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(s.cameraBack - glm::dvec3(0.0, -1.0, 0.0)), 0.0, 1e-15);
    clock.setTime(50.0); // after the last key: held at it
    EXPECT_EQ(clock.next(false).cameraPositionKm, glm::dvec3(0.0, 100.0, 6441.0));
    EXPECT_TRUE(clock.camera().path.empty()); // the pose shown, not the path
    // Put elsewhere without a path (the remote control's goto), the camera stays there.
    scene::Camera still = clock.camera();
    still.positionKm = {6500.0, 0.0, 0.0};
    clock.setCamera(still);
    clock.setTime(5.0);
    EXPECT_EQ(clock.next(false).cameraPositionKm, glm::dvec3(6500.0, 0.0, 0.0));
}

// Every frame announces the next one's time: with no command between, the next frame shows exactly it
// (fixed steps, paused, after a jump); a command in between may change it.
TEST(MasterClock, EachFrameAnnouncesTheNextFramesTime)
{
    MasterClock clock(fixedStep(3.0, 0.1), flyingCamera(), 1.0);
    FrameState s = clock.next(false);
    for (int n = 0; n < 50; ++n) {
        const FrameState next = clock.next(false);
        ASSERT_EQ(next.timeS, s.nextTimeS) << "frame " << next.frame;
        ASSERT_GT(next.timeS, s.timeS);
        s = next;
    }
    clock.pause();
    s = clock.next(false);
    EXPECT_EQ(s.nextTimeS, s.timeS);
    EXPECT_EQ(clock.next(false).timeS, s.nextTimeS);
    clock.setTime(40.0);
    clock.play();
    s = clock.next(false);
    EXPECT_EQ(s.timeS, 40.0);
    EXPECT_EQ(s.nextTimeS, 40.1);
    EXPECT_EQ(clock.next(false).timeS, 40.1);
}

// Real time: frame n + 1 shows speed x the wall-clock time from the anchor to the moment frame n began,
// exactly the time frame n announced; the time never runs backwards and keeps up with the clock.
TEST(MasterClock, RealTimeFramesShowTheTimeTheirPredecessorAnnounced)
{
    ClockSettings settings = fixedStep(100.0, 0.5);
    settings.realTime = true;
    MasterClock clock(settings, flyingCamera(), 1.0);
    clock.setSpeed(2.0);
    FrameState s = clock.next(false);
    EXPECT_EQ(s.timeS, 100.0);
    const auto start = std::chrono::steady_clock::now();
    for (int n = 0; n < 5; ++n) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        const FrameState next = clock.next(false);
        ASSERT_EQ(next.timeS, s.nextTimeS) << "frame " << next.frame;
        ASSERT_GE(next.timeS, s.timeS);
        ASSERT_GE(next.nextTimeS, next.timeS + 2.0 * 0.020); // at least 20 ms of the clock at speed 2
        s = next;
    }
    // Frame 6 shows the moment frame 5 began: at least 4 sleeps after frame 1 began, on the clock.
    const double sinceFirstS = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_GE(s.timeS, 100.0 + 2.0 * 0.080);
    EXPECT_LE(s.timeS, 100.0 + 2.0 * sinceFirstS);
    clock.pause(); // a command between frames: the next frame shows the time shown, still
    const double shown = clock.timeS();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    EXPECT_EQ(clock.next(false).timeS, shown);
}
