// The browser console's pieces without a server: the mailbox between the web threads and the frame
// loop, the channels joined for serveCommands, and the status line as JSON.
#include "app/control/command_channel.h"
#include "app/web/command_mailbox.h"
#include "app/web/downloads.h"
#include "app/web/movie_archive.h"
#include "app/web/status_json.h"
#include "app/path_recorder.h"
#include "components/registry.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <thread>

namespace aw = aurorawall;

TEST(CommandMailbox, AnAskIsAnsweredByTheFrameLoop)
{
    aw::app::web::CommandMailbox mailbox;
    std::thread frameLoop([&] {
        for (int tries = 0; tries < 1000; ++tries) {
            const std::vector<aw::app::control::ControlLine> lines = mailbox.poll(16);
            if (!lines.empty()) {
                mailbox.answer(lines[0].client, "ok " + lines[0].text);
                return;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
    });
    EXPECT_EQ(mailbox.ask("pause", 10.0), std::optional<std::string>("ok pause"));
    frameLoop.join();
}

TEST(CommandMailbox, AnUnansweredAskIsWithdrawn)
{
    aw::app::web::CommandMailbox mailbox;
    EXPECT_FALSE(mailbox.ask("quit", 0.01));
    EXPECT_TRUE(mailbox.poll(16).empty()); // not carried out later
    mailbox.answer(1, "ok quit");           // an answer nobody waits for is dropped
}

TEST(CommandMailbox, ClosedAnswersNothing)
{
    aw::app::web::CommandMailbox mailbox;
    mailbox.close();
    EXPECT_FALSE(mailbox.ask("status", 10.0)); // at once
}

namespace {
struct Recorder : aw::app::control::CommandChannel {
    std::vector<aw::app::control::ControlLine> lines;
    std::vector<std::pair<std::uint64_t, std::string>> answers;
    std::vector<aw::app::control::ControlLine> poll(std::size_t maxLines) override
    {
        std::vector<aw::app::control::ControlLine> out(lines.begin(), lines.begin() + std::min(maxLines, lines.size()));
        lines.erase(lines.begin(), lines.begin() + out.size());
        return out;
    }
    void answer(std::uint64_t client, const std::string& text) override { answers.push_back({client, text}); }
};
} // namespace

TEST(ChannelSet, AnswersFindTheirChannelAndClient)
{
    Recorder a, b;
    a.lines = {{7, "status"}, {7, "pause"}};
    b.lines = {{7, "play"}};
    aw::app::control::ChannelSet set;
    set.add(a);
    set.add(b);
    const std::vector<aw::app::control::ControlLine> lines = set.poll(2); // one each
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[0].text, "status");
    EXPECT_EQ(lines[1].text, "play");
    EXPECT_NE(lines[0].client, lines[1].client); // client 7 of each, told apart
    set.answer(lines[1].client, "ok playing");
    set.answer(lines[0].client, "ok frame=1");
    ASSERT_EQ(b.answers.size(), 1u);
    EXPECT_EQ(b.answers[0], std::make_pair(std::uint64_t(7), std::string("ok playing")));
    ASSERT_EQ(a.answers.size(), 1u);
    EXPECT_EQ(a.answers[0].first, 7u);
}

TEST(StatusJson, MembersFromTheStatusLine)
{
    EXPECT_EQ(aw::app::web::statusJson("ok frame=12 time_s=1e+15 fps=9.5 paused speed=1 lat_deg=-65.000000"),
              R"({"frame":12,"time_s":1e+15,"fps":9.5,"paused":true,"speed":1,"lat_deg":-65.000000})");
    EXPECT_EQ(aw::app::web::statusJson("ok frame=1 playing name=inf"), R"({"frame":1,"paused":false,"name":"inf"})");
    EXPECT_THROW(aw::app::web::statusJson("error the wall is quitting"), std::invalid_argument);
}

TEST(RanksJson, EachRanksFrameTimesAndHeartbeatAge)
{
    aw::cluster::FrameRecord record{7, 3.5, 40.0, {}};
    record.ranks.resize(2);
    record.ranks[0].frame = 7;
    record.ranks[0].renderMs = 20.0;
    record.ranks[0].waitMs = 1.5;
    record.ranks[1].frame = 6;
    record.ranks[1].renderMs = 30.0;
    record.ranks[1].waitMs = 0.25;
    EXPECT_EQ(aw::app::web::ranksJson(record, {0.0, 0.375}, 1.0),
              R"({"frame":7,"imbalance":1.2,"heartbeat_period_s":1,"ranks":[)"
              R"({"frame":7,"render_ms":20,"wait_ms":1.5,"heartbeat_age_s":0},)"
              R"({"frame":6,"render_ms":30,"wait_ms":0.25,"heartbeat_age_s":0.375}]})");
    // Without a watchdog (no MPI_THREAD_MULTIPLE): no ages, no period.
    EXPECT_EQ(aw::app::web::ranksJson(record, {}, 1.0),
              R"({"frame":7,"imbalance":1.2,"heartbeat_period_s":null,"ranks":[)"
              R"({"frame":7,"render_ms":20,"wait_ms":1.5,"heartbeat_age_s":null},)"
              R"({"frame":6,"render_ms":30,"wait_ms":0.25,"heartbeat_age_s":null}]})");
}

namespace {
// A fresh folder under the system's temporary one.
std::filesystem::path freshFolder(const std::string& name)
{
    const std::filesystem::path folder = std::filesystem::temp_directory_path() /
                                         ("aw-web-test-" + std::to_string(::getpid()) + "-" + name);
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

std::string readText(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}
} // namespace

// Every shipped scene (the derived ones two files deep) recorded, downloaded and saved elsewhere
// reads as the recording does, with no other file: the same name, components, times, exposure and
// camera keys, and no base.
TEST(RecordingForDownload, EmbedsTheBaseScenesAndReadsAsTheRecording)
{
    namespace fs = std::filesystem;
    const fs::path recorded = freshFolder("recorded"), elsewhere = freshFolder("elsewhere");
    int scenes = 0;
    for (const auto& entry : fs::directory_iterator(AW_SCENES_DIR)) {
        if (entry.path().extension() != ".toml")
            continue;
        const std::string file = (recorded / "flight.toml").string();
        aw::app::PathRecorder recorder(file, entry.path().string(), 100.0, 0.25);
        aw::cluster::FrameState state;
        state.timeS = 100.0;
        state.cameraPositionKm = {6500.0, 10.0, 20.0};
        recorder.add(state);
        state.timeS = 100.25;
        state.cameraPositionKm = {6500.5, 10.25, 20.125};
        state.zoom = 1.5;
        recorder.add(state);
        recorder.write();
        const std::string copy = (elsewhere / (entry.path().stem().string() + ".toml")).string();
        std::ofstream(copy, std::ios::binary) << aw::app::web::recordingForDownload(readText(file), recorded.string());
        EXPECT_EQ(readText(copy).find("base ="), std::string::npos) << copy;
        const aw::scene::Scene original = aw::components::loadScene(file);
        aw::scene::Scene embedded;
        ASSERT_NO_THROW(embedded = aw::components::loadScene(copy)) << readText(copy);
        EXPECT_EQ(embedded.name, original.name) << copy;
        EXPECT_EQ(embedded.startTimeS, original.startTimeS);
        EXPECT_EQ(embedded.timeStepS, original.timeStepS);
        EXPECT_EQ(embedded.exposure, original.exposure);
        EXPECT_EQ(embedded.planetRadiusKm, original.planetRadiusKm);
        ASSERT_EQ(embedded.components().size(), original.components().size()) << copy;
        for (std::size_t i = 0; i < original.components().size(); ++i)
            EXPECT_EQ(embedded.components()[i]->name(), original.components()[i]->name());
        EXPECT_EQ(embedded.camera.positionKm, original.camera.positionKm);
        EXPECT_EQ(embedded.camera.path.empty(), original.camera.path.empty());
        ++scenes;
    }
    EXPECT_GE(scenes, 10);
    fs::remove_all(recorded);
    fs::remove_all(elsewhere);
}

TEST(RecordingForDownload, TextWithoutABaseStaysAsItIs)
{
    const std::string none = "[scene]\nstart_time_s = 1.0\n";
    EXPECT_EQ(aw::app::web::recordingForDownload(none, "/out"), none);
}

TEST(RecordingForDownload, AMissingBaseSceneIsNamed)
{
    const std::string text = "[scene]\nbase = \"gone.toml\"\n";
    try {
        aw::app::web::recordingForDownload(text, "/nowhere");
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("/nowhere/gone.toml: the base scene cannot be read"), std::string::npos)
            << e.what();
    }
}

// A movie's folder as a zip: only the movie writer's files, in order, each stored whole under NAME/;
// a client that goes away ends the archive with an error.
TEST(MovieArchive, TheFramesAndTheirTimesAsAZip)
{
    namespace fs = std::filesystem;
    const fs::path folder = freshFolder("movie");
    std::ofstream(folder / "frame-000001.png", std::ios::binary) << "png one";
    std::ofstream(folder / "frame-000000.png", std::ios::binary) << "png zero";
    std::ofstream(folder / "frame-000000.exr", std::ios::binary) << std::string(100000, 'e');
    std::ofstream(folder / "frames.csv", std::ios::binary) << "frame,time_s\n0,1\n1,2\n";
    std::ofstream(folder / "frames.csv.tmp123", std::ios::binary) << "half";
    std::ofstream(folder / "notes.txt", std::ios::binary) << "not the movie's";
    fs::create_directory(folder / "frame-000002.png");
    fs::create_symlink("/etc/passwd", folder / "frame-000003.png");
    const std::vector<aw::app::web::MovieFile> files = aw::app::web::movieFiles(folder.string());
    std::vector<std::string> names;
    for (const auto& f : files)
        names.push_back(f.name);
    EXPECT_EQ(names, (std::vector<std::string>{"frame-000000.exr", "frame-000000.png", "frame-000001.png", "frames.csv"}));
    std::string zip;
    EXPECT_EQ(aw::app::web::writeMovieZip(folder.string(), files, "clip", [&](const char* data, std::size_t n) {
                  zip.append(data, n);
                  return true;
              }),
              "");
    EXPECT_EQ(zip.substr(0, 4), std::string("PK\x03\x04", 4));
    EXPECT_NE(zip.find("clip/frame-000001.png"), std::string::npos);
    EXPECT_NE(zip.find(std::string(100000, 'e')), std::string::npos); // stored, not compressed
    EXPECT_NE(zip.find(std::string("PK\x05\x06", 4)), std::string::npos); // the end of the central directory
    std::size_t sent = 0;
    EXPECT_EQ(aw::app::web::writeMovieZip(folder.string(), files, "clip", [&](const char*, std::size_t n) {
                  sent += n;
                  return sent < 70000;
              }),
              "the client went away");
    fs::remove(folder / "frame-000001.png");
    EXPECT_NE(aw::app::web::writeMovieZip(folder.string(), files, "clip", [](const char*, std::size_t) { return true; })
                  .find("frame-000001.png"),
              std::string::npos);
    EXPECT_THROW(aw::app::web::movieFiles((folder / "none").string()), std::runtime_error);
    fs::remove_all(folder);
}

TEST(StatusJson, AMemberAdded)
{
    EXPECT_EQ(aw::app::web::withMember("{\"frame\":1}", "movie_error", "frame 2: \"x\" full"),
              "{\"frame\":1,\"movie_error\":\"frame 2: \\\"x\\\" full\"}");
    EXPECT_EQ(aw::app::web::withMember("{}", "a", "b"), "{\"a\":\"b\"}");
}
