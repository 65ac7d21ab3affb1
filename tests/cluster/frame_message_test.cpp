// The frame's two messages survive their byte form: the master's FrameMessage (one broadcast) and
// each rank's RankMessage (one gather), and malformed bytes are refused.
#include "cluster/frame_message.h"
#include "cluster/rank_message.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

using namespace aurorawall::cluster;

namespace {

FrameMessage sampleFrame()
{
    FrameMessage m;
    m.state.frame = 1234567890123ull;
    m.state.timeS = 1e9 + 0.125;
    m.state.cameraPositionKm = {6441.5, -12.25, 3.0e-7};
    m.state.cameraRight = {0.0, 0.6, 0.8};
    m.state.cameraUp = {1.0, 0.0, 0.0};
    m.state.cameraBack = {0.0, 0.8, -0.6};
    m.state.exposure = 3.5;
    m.state.quit = 1;
    m.assignment = {0, 3, 3, 1, 2, 0, 1};
    m.events = {{1, 65, 12.5, -3.0}, {2, 0, 639.5, 359.5}};
    m.hud = {"FPS 9.5  T 120.00 S", "", std::string(kHudColumns, '#')};
    return m;
}

// The events `sent`, each field of each, are the events `got`.
void expectTheSameEvents(const std::vector<InputEvent>& got, const std::vector<InputEvent>& sent)
{
    ASSERT_EQ(got.size(), sent.size());
    for (size_t i = 0; i < sent.size(); ++i) {
        EXPECT_EQ(got[i].type, sent[i].type) << "event " << i;
        EXPECT_EQ(got[i].code, sent[i].code) << "event " << i;
        EXPECT_EQ(got[i].x, sent[i].x) << "event " << i;
        EXPECT_EQ(got[i].y, sent[i].y) << "event " << i;
    }
}

} // namespace

TEST(FrameMessage, RoundTripKeepsEveryField)
{
    const FrameMessage sent = sampleFrame();
    const std::vector<char> bytes = packFrameMessage(sent, sent.assignment.size());
    ASSERT_EQ(bytes.size(), frameMessageBytes(sent.assignment.size()));
    const FrameMessage got = unpackFrameMessage(bytes, sent.assignment.size());
    EXPECT_EQ(got.state.frame, sent.state.frame);
    EXPECT_EQ(got.state.timeS, sent.state.timeS);
    EXPECT_EQ(got.state.cameraPositionKm, sent.state.cameraPositionKm);
    EXPECT_EQ(got.state.cameraRight, sent.state.cameraRight);
    EXPECT_EQ(got.state.cameraUp, sent.state.cameraUp);
    EXPECT_EQ(got.state.cameraBack, sent.state.cameraBack);
    EXPECT_EQ(got.state.exposure, sent.state.exposure);
    EXPECT_EQ(got.state.quit, sent.state.quit);
    EXPECT_EQ(got.assignment, sent.assignment);
    ASSERT_NO_FATAL_FAILURE(expectTheSameEvents(got.events, sent.events));
    EXPECT_EQ(got.hud, sent.hud);
}

// Every frame's message has one size for a given band count, however many events it carries, so
// the broadcast needs no size first.
TEST(FrameMessage, SizeDependsOnlyOnTheBandCount)
{
    FrameMessage m = sampleFrame();
    const size_t bands = m.assignment.size();
    m.events.clear();
    EXPECT_EQ(packFrameMessage(m, bands).size(), frameMessageBytes(bands));
    EXPECT_TRUE(unpackFrameMessage(packFrameMessage(m, bands), bands).events.empty());
    m.events.assign(kMaxInputEvents, InputEvent{7, 8, 9.0, 10.0});
    EXPECT_EQ(packFrameMessage(m, bands).size(), frameMessageBytes(bands));
    EXPECT_EQ(unpackFrameMessage(packFrameMessage(m, bands), bands).events.size(), kMaxInputEvents);
    m.hud.assign(kHudLines, std::string(kHudColumns, 'W'));
    EXPECT_EQ(packFrameMessage(m, bands).size(), frameMessageBytes(bands));
    EXPECT_EQ(unpackFrameMessage(packFrameMessage(m, bands), bands).hud, m.hud);
    m.hud.clear();
    EXPECT_TRUE(unpackFrameMessage(packFrameMessage(m, bands), bands).hud.empty());
    EXPECT_GT(frameMessageBytes(bands + 1), frameMessageBytes(bands));
}

TEST(FrameMessage, RefusesWhatDoesNotFit)
{
    FrameMessage m = sampleFrame();
    const size_t bands = m.assignment.size();
    EXPECT_THROW(packFrameMessage(m, bands + 1), std::invalid_argument);
    m.events.assign(kMaxInputEvents + 1, InputEvent{});
    EXPECT_THROW(packFrameMessage(m, bands), std::invalid_argument);
    m = sampleFrame();
    m.hud.assign(kHudLines + 1, "");
    EXPECT_THROW(packFrameMessage(m, bands), std::invalid_argument);
    m.hud = {std::string(kHudColumns + 1, 'X')};
    EXPECT_THROW(packFrameMessage(m, bands), std::invalid_argument);

    const std::vector<char> bytes = packFrameMessage(sampleFrame(), bands);
    EXPECT_THROW(unpackFrameMessage(bytes, bands + 1), std::runtime_error); // size of another wall
    std::vector<char> shorter(bytes.begin(), bytes.end() - 1);
    EXPECT_THROW(unpackFrameMessage(shorter, bands), std::runtime_error);
    std::vector<char> badCount = bytes;
    badCount[sizeof(FrameState) + sizeof(std::int32_t)] = static_cast<char>(kMaxInputEvents + 1); // event count
    EXPECT_THROW(unpackFrameMessage(badCount, bands), std::runtime_error);
    std::vector<char> badHud = bytes;
    badHud[sizeof(FrameState) + 2 * sizeof(std::int32_t)] = static_cast<char>(kHudLines + 1); // HUD line count
    EXPECT_THROW(unpackFrameMessage(badHud, bands), std::runtime_error);
}

TEST(RankMessage, RoundTripOfSeveralRanks)
{
    const size_t bands = 5;
    std::vector<char> gathered;
    std::vector<RankMessage> sent(3);
    for (int r = 0; r < 3; ++r) {
        RankReport& report = sent[r].report;
        report.frame = 41;
        report.timeS = 180.5;
        report.prepareMs = 7.25 + r;
        report.prepareCpuMs = 7.0 + r;
        report.renderMs = 100.0 * (r + 1);
        report.renderCpuMs = 99.0 * (r + 1);
        report.renderGpuMs = r == 1 ? -1.0 : 95.5 * (r + 1);
        report.exchangeMs = 0.5 * r;
        report.exchangeMB = 0.125 * r;
        report.renderWork = 1e6 * (r + 1);
        report.waitMs = 3.0 - r;
        report.swapMs = 0.25;
        report.closeRequested = r == 2;
    }
    sent[0].costs = {{0, 10.5, 1000.0}, {4, 0.25, 20.0}};
    sent[2].costs = {{1, 3.0, 300.0}, {2, 4.0, 400.0}, {3, 5.0, 500.0}};
    sent[1].events = {{1, 87, 0.0, 0.0}, {2, 0, -12.5, 3.25}};
    sent[2].events.assign(kMaxInputEvents, InputEvent{1, 258, 0.0, 0.0});
    for (const RankMessage& m : sent) {
        const std::vector<char> bytes = packRankMessage(m, bands);
        ASSERT_EQ(bytes.size(), rankMessageBytes(bands));
        gathered.insert(gathered.end(), bytes.begin(), bytes.end());
    }
    const std::vector<RankMessage> got = unpackRankMessages(gathered, bands);
    ASSERT_EQ(got.size(), 3u);
    for (int r = 0; r < 3; ++r) {
        const RankReport &a = got[r].report, &b = sent[r].report;
        EXPECT_EQ(a.frame, b.frame);
        EXPECT_EQ(a.timeS, b.timeS);
        EXPECT_EQ(a.prepareMs, b.prepareMs);
        EXPECT_EQ(a.prepareCpuMs, b.prepareCpuMs);
        EXPECT_EQ(a.renderMs, b.renderMs);
        EXPECT_EQ(a.renderCpuMs, b.renderCpuMs);
        EXPECT_EQ(a.renderGpuMs, b.renderGpuMs);
        EXPECT_EQ(a.exchangeMs, b.exchangeMs);
        EXPECT_EQ(a.exchangeMB, b.exchangeMB);
        EXPECT_EQ(a.renderWork, b.renderWork);
        EXPECT_EQ(a.waitMs, b.waitMs);
        EXPECT_EQ(a.swapMs, b.swapMs);
        EXPECT_EQ(a.closeRequested, b.closeRequested);
        ASSERT_EQ(got[r].costs.size(), sent[r].costs.size()) << "rank " << r;
        for (size_t i = 0; i < sent[r].costs.size(); ++i) {
            EXPECT_EQ(got[r].costs[i].band, sent[r].costs[i].band);
            EXPECT_EQ(got[r].costs[i].cpuMs, sent[r].costs[i].cpuMs);
            EXPECT_EQ(got[r].costs[i].work, sent[r].costs[i].work);
        }
        ASSERT_NO_FATAL_FAILURE(expectTheSameEvents(got[r].events, sent[r].events)) << "rank " << r;
    }

    // The balancer's input: one value per band by the chosen measure, NaN where nobody drew it.
    const std::vector<double> time = bandCosts(got, bands, BandMeasure::Time);
    EXPECT_EQ(time, (std::vector<double>{10.5, 3.0, 4.0, 5.0, 0.25}));
    const std::vector<double> work = bandCosts(got, bands, BandMeasure::Work);
    EXPECT_EQ(work, (std::vector<double>{1000.0, 300.0, 400.0, 500.0, 20.0}));
    EXPECT_TRUE(std::isnan(bandCosts({got[0]}, bands, BandMeasure::Work)[1]));
}

TEST(RankMessage, RefusesWhatDoesNotFit)
{
    RankMessage m;
    m.costs.assign(3, BandCost{});
    EXPECT_THROW(packRankMessage(m, 2), std::invalid_argument);
    m.costs = {{7, 1.0, 1.0}};
    const std::vector<char> bytes = packRankMessage(m, 8);
    EXPECT_THROW(unpackRankMessages(bytes, 7), std::runtime_error); // not a whole number of messages
    EXPECT_EQ(unpackRankMessages(bytes, 8)[0].costs[0].band, 7);
    EXPECT_THROW(unpackRankMessages(packRankMessage(m, 7), 7), std::runtime_error); // band 7 of 0..6

    RankMessage keys;
    keys.events.assign(kMaxInputEvents + 1, InputEvent{});
    EXPECT_THROW(packRankMessage(keys, 2), std::invalid_argument);
    keys.events.pop_back();
    std::vector<char> tooMany = packRankMessage(keys, 2);
    const std::int32_t count = kMaxInputEvents + 1; // the event count follows the report and the cost count
    std::memcpy(tooMany.data() + sizeof(RankReport) + sizeof(std::int32_t), &count, sizeof count);
    EXPECT_THROW(unpackRankMessages(tooMany, 2), std::runtime_error);
}
