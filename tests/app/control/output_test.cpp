// The output folder's path rules (screenshot, record start, movie start) and the refusals of
// record and movie by what runs: one recording and one movie at a time, a stop only while one runs.
#include "app/control/command.h"
#include "app/control/output_path.h"
#include "app/control/remote_control.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

using namespace aurorawall;
using namespace aurorawall::app::control;

namespace {

std::string refusal(const std::string& what, const std::string& path, const std::string& out)
{
    try {
        insideOutputFolder(what, path, out);
    } catch (const CommandError& e) {
        return e.what();
    }
    return "accepted";
}

// An output folder with a subfolder, made afresh (one per test: ctest may run them at once).
std::string outputFolder(const std::string& test)
{
    const std::filesystem::path out =
        std::filesystem::temp_directory_path() / ("aw-output-test-" + test + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(out);
    std::filesystem::create_directories(out / "sub");
    return out.string();
}

struct Lines : CommandChannel {
    std::vector<ControlLine> lines;
    std::vector<std::string> answers;
    std::vector<ControlLine> poll(std::size_t) override { return std::exchange(lines, {}); }
    void answer(std::uint64_t, const std::string& text) override { answers.push_back(text); }
};

// Serves `text` (one line each) against `status`; the requests handed to the frame loop and the answers.
FrameRequests serve(const std::vector<std::string>& text, const WallStatus& status, const std::string& out,
                    std::vector<std::string>& answers)
{
    Lines channel;
    for (const std::string& t : text)
        channel.lines.push_back({1, t});
    cluster::ClockSettings settings;
    cluster::MasterClock clock(settings, scene::Camera{}, 1.0);
    PresetLoader presets;
    const FrameRequests requests = serveCommands(channel, clock, status, WallFacts{6371.0, "", out}, presets);
    answers = channel.answers;
    return requests;
}

} // namespace

TEST(OutputPath, OnlyInsideTheOutputFolder)
{
    const std::string out = outputFolder("inside");
    EXPECT_EQ(insideOutputFolder("x", "a.png", out), std::filesystem::path(out) / "a.png");
    EXPECT_EQ(insideOutputFolder("x", "sub/a b.toml", out), std::filesystem::path(out) / "sub/a b.toml");
    EXPECT_EQ(refusal("record start /tmp/a.toml", "/tmp/a.toml", out),
              "record start /tmp/a.toml: an absolute path; give a path inside the output folder (--out " + out + ")");
    EXPECT_EQ(refusal("w ../a.png", "../a.png", out), "w ../a.png: '..' would leave the output folder (--out " + out + ")");
    EXPECT_NE(refusal("w", "sub/../../a.png", out).find("'..' would leave"), std::string::npos);
    EXPECT_NE(refusal("w", "sub/x/..", out).find("'..' would leave"), std::string::npos);
    EXPECT_EQ(refusal("w", "none/a.png", out), "w: " + out + "/none is not a folder");
    std::filesystem::remove_all(out);
}

TEST(OutputPath, RecordAndMovieRefusedByWhatRuns)
{
    const std::string out = outputFolder("refused");
    std::vector<std::string> answers;
    // Nothing runs: the stops refused, the starts handed to the frame loop (unanswered until it acts).
    FrameRequests r = serve({"record stop", "movie stop", "record start a.toml", "movie start m"}, {}, out, answers);
    ASSERT_EQ(answers.size(), 2u);
    EXPECT_EQ(answers[0], "error record stop: no recording runs (record start PATH.toml starts one)");
    EXPECT_EQ(answers[1], "error movie stop: no movie runs (movie start DIR starts one)");
    ASSERT_EQ(r.outputs.size(), 2u);
    EXPECT_EQ(r.outputs[0].kind, CommandKind::RecordStart);
    EXPECT_EQ(r.outputs[0].name, "a.toml");
    EXPECT_EQ(r.outputs[0].path, out + "/a.toml");
    EXPECT_EQ(r.outputs[1].path, out + "/m");
    EXPECT_FALSE(r.outputs[1].exr);
    r = serve({"movie start exr e"}, {}, out, answers);
    ASSERT_EQ(r.outputs.size(), 1u);
    EXPECT_EQ(r.outputs[0].path, out + "/e");
    EXPECT_TRUE(r.outputs[0].exr);

    // Asked twice in one frame: the second start refused; a stop then a start again accepted.
    r = serve({"record start a.toml", "record start b.toml", "record stop", "record start c.toml"}, {}, out, answers);
    ASSERT_EQ(answers.size(), 1u);
    EXPECT_EQ(answers[0], "error record start b.toml: a recording into " + out + "/a.toml runs (record stop first)");
    ASSERT_EQ(r.outputs.size(), 3u);
    EXPECT_EQ(r.outputs[1].kind, CommandKind::RecordStop);
    EXPECT_EQ(r.outputs[1].path, out + "/a.toml");

    // Running: a start refused, the stop names what it stops.
    WallStatus running;
    running.recording = out + "/a.toml";
    running.movie = out + "/m";
    r = serve({"record start b.toml", "movie start n", "record stop", "movie stop"}, running, out, answers);
    ASSERT_EQ(answers.size(), 2u);
    EXPECT_EQ(answers[1], "error movie start n: a movie into " + out + "/m runs (movie stop first)");
    ASSERT_EQ(r.outputs.size(), 2u);
    EXPECT_EQ(r.outputs[1].kind, CommandKind::MovieStop);
    EXPECT_EQ(r.outputs[1].path, out + "/m");

    // Paths: a folder for a recording, a file or an old movie for a movie, outside the folder.
    std::ofstream(out + "/file");
    std::filesystem::create_directory(out + "/old");
    std::ofstream(out + "/old/frames.csv");
    serve({"record start sub.toml/../x.toml", "movie start file", "movie start old", "movie start ../m"}, {}, out,
          answers);
    std::filesystem::create_directory(out + "/dir.toml");
    std::vector<std::string> more;
    serve({"record start dir.toml"}, {}, out, more);
    ASSERT_EQ(answers.size(), 4u);
    EXPECT_NE(answers[0].find("'..' would leave the output folder"), std::string::npos) << answers[0];
    EXPECT_EQ(answers[1], "error movie start file: " + out + "/file is not a folder");
    EXPECT_EQ(answers[2], "error movie start old: " + out + "/old already holds a movie (frames.csv); give another folder");
    EXPECT_NE(answers[3].find("'..' would leave"), std::string::npos);
    ASSERT_EQ(more.size(), 1u);
    EXPECT_EQ(more[0], "error record start dir.toml: " + out + "/dir.toml is a folder");
    std::filesystem::remove_all(out);
}
