#include "app/frame_loop.h"

#include "app/band_frame.h"
#include "app/band_split.h"
#include "app/control/remote_control.h"
#include "app/navigation.h"
#include "app/path_recorder.h"
#include "app/wall_output.h"
#include "cluster/frame_message.h"
#include "cluster/master_clock.h"
#include "cluster/rank_message.h"
#include "common/clock.h"
#include "io/png.h"

#include <cstdio>
#include <optional>
#include <stdexcept>

namespace aurorawall::app {

namespace {

cluster::ClockSettings clockSettings(const WallSession& s)
{
    cluster::ClockSettings c;
    c.frames = static_cast<std::uint64_t>(s.options.frames);
    c.startTimeS = s.options.startTimeGiven ? s.options.startTimeS : s.scene.startTimeS;
    c.timeStepS = s.options.timeStepS >= 0 ? s.options.timeStepS : s.scene.timeStepS;
    c.realTime = s.options.realTime;
    return c;
}

// This rank's window events since its last message, as they travel to the master.
std::vector<cluster::InputEvent> windowEvents(gl::Context& context)
{
    std::vector<cluster::InputEvent> events;
    for (const gl::InputEvent& e : context.takeInputEvents(cluster::kMaxInputEvents))
        events.push_back({e.type, e.key, e.dx, e.dy});
    return events;
}

double pixelsPerFrame(const wall::Wall& wall)
{
    double pixels = 0;
    for (const wall::Screen& s : wall.screens)
        pixels += double(s.widthPx) * s.heightPx;
    return pixels;
}

// The master writes the gathered wall for each screenshot asked for and answers its client.
void writeScreenshots(WallSession& session, const io::Image& canvas, int gatherStatus,
                      const std::vector<control::ScreenshotRequest>& screenshots)
{
    for (const control::ScreenshotRequest& shot : screenshots) {
        std::string answer = "ok screenshot " + shot.path;
        try {
            if (gatherStatus != 0)
                throw std::runtime_error("the wall could not be read back");
            io::writePng(shot.path, canvas, session.toneMap); // atomic: a temporary name, then renamed
        } catch (const std::exception& e) {
            answer = "error screenshot " + shot.path + ": " + e.what();
        }
        session.control->answer(shot.client, answer);
    }
}

// The master writes the frame's wall into the movie; on a failure it says why once and stops the run
// (the movie would have a hole), which then exits 1.
void writeMovieFrame(WallSession& session, MovieWriter& movie, const io::Image& canvas, int gatherStatus,
                     const cluster::FrameState& state, bool& stopRequested)
{
    if (!session.movieError.empty())
        return;
    try {
        if (gatherStatus != 0)
            throw std::runtime_error("the wall could not be read back");
        movie.write(canvas, state);
    } catch (const std::exception& e) {
        session.movieError = "--movie " + session.options.movieDir + ": " + e.what();
        stopRequested = true;
    }
}

} // namespace

cluster::FrameStats runFrames(WallSession& session, const cluster::MpiWorld& world)
{
    const size_t bandCount = session.bands.size();
    // The master alone keeps the clock and splits the bands.
    std::optional<cluster::MasterClock> clock;
    std::optional<BandSplit> split;
    Navigation navigation(session.scene.planetRadiusKm);
    std::vector<cluster::InputEvent> navigationEvents; // every rank's, gathered with the last frame
    if (world.isMaster()) {
        clock.emplace(clockSettings(session), session.scene.camera, session.exposure);
        split.emplace(session.bands, world.size(), session.balanced,
                      session.options.balanceBy);
    }
    BandFrame bands(session.wall, session.bands, world.rank(), session.balanced);
    cluster::FrameStats stats(pixelsPerFrame(session.wall));
    bool stopRequested = false;
    control::WallStatus wallStatus;
    std::vector<control::ScreenshotRequest> screenshots;
    std::optional<MovieWriter> movie;
    if (world.isMaster() && !session.options.movieDir.empty())
        movie.emplace(session.options.movieDir, session.options.movieExr, session.toneMap);
    std::optional<PathRecorder> recorder;
    if (world.isMaster() && !session.options.recordPath.empty()) {
        const cluster::ClockSettings c = clockSettings(session);
        recorder.emplace(session.options.recordPath, session.options.sceneFile, c.startTimeS, c.timeStepS);
    }
    std::vector<char> message(cluster::frameMessageBytes(bandCount));
    auto waitStart = SteadyClock::now(); // from this rank's previous report to this frame's message
    auto previousFrameStart = SteadyClock::now();
    while (true) {
        // 1. The master flies the camera by the window events of the last frame, carries out the
        // remote control's commands and decides the frame; one broadcast tells every rank.
        const auto frameStart = SteadyClock::now();
        if (world.isMaster()) {
            if (!navigationEvents.empty())
                clock->setCamera(navigation.apply(clock->camera(), navigationEvents));
            navigationEvents.clear();
            if (session.control) {
                if (!stats.records().empty()) // over the last frame: drawing, gathering, commands
                    wallStatus.fps = 1.0 / std::chrono::duration<double>(frameStart - previousFrameStart).count();
                const control::FrameRequests requests =
                    control::serveCommands(*session.control, *clock, wallStatus, session.scene.planetRadiusKm);
                stopRequested = stopRequested || requests.quit;
                screenshots = requests.screenshots;
            }
            cluster::FrameState state = clock->next(stopRequested);
            state.gatherWall = !screenshots.empty() || movie.has_value();
            if (recorder && !state.quit)
                recorder->add(state);
            message = cluster::packFrameMessage({state, split->next(), {}}, bandCount);
        }
        previousFrameStart = frameStart;
        world.broadcast(message);
        const cluster::FrameMessage frame = cluster::unpackFrameMessage(message, bandCount);
        world.setPhase(cluster::RankPhase::Draw, frame.state.frame);
        if (frame.state.quit) {
            for (const control::ScreenshotRequest& shot : screenshots)
                session.control->answer(shot.client, "error screenshot " + shot.path + ": the wall is quitting");
            break;
        }
        cluster::RankMessage mine;
        cluster::RankReport& report = mine.report;
        report.frame = frame.state.frame;
        report.timeS = frame.state.timeS;
        report.waitMs = millisecondsSince(waitStart);

        // 2. Every rank draws its bands and exchanges those drawn away from their screen.
        auto phase = SteadyClock::now();
        const double prepareCpuStart = processCpuMilliseconds();
        session.renderer->setFrame(frame.state);
        report.prepareMs = millisecondsSince(phase);
        report.prepareCpuMs = processCpuMilliseconds() - prepareCpuStart;
        mine.costs = bands.draw(*session.renderer, *session.context, session.screens, frame.assignment, world, report);

        // 3. Windows show the screens' targets and flip together: the swap barrier makes every rank
        // wait until all have drawn into their back buffers, so no screen shows the next frame early.
        if (session.presenter) {
            for (ScreenTarget& s : session.screens)
                session.presenter->present(*session.context, s.window, *s.target, *s.triangle);
            phase = SteadyClock::now();
            world.swapBarrier();
            report.waitMs += millisecondsSince(phase);
            phase = SteadyClock::now();
            for (ScreenTarget& s : session.screens)
                session.context->swapBuffers(s.window);
            session.context->pollEvents();
            report.closeRequested = session.context->closeRequested();
            mine.events = windowEvents(*session.context);
            report.swapMs = millisecondsSince(phase);
            session.context->makeCurrent(0);
        }

        // 4. One gather: the master learns what every rank drew, how long it took, what its bands
        // cost, what was pressed in its windows, and whether to stop.
        waitStart = SteadyClock::now();
        world.setPhase(cluster::RankPhase::Gather, frame.state.frame);
        const std::vector<char> gathered = world.gather(cluster::packRankMessage(mine, bandCount));
        if (world.isMaster()) {
            const std::vector<cluster::RankMessage> ranks = cluster::unpackRankMessages(gathered, bandCount);
            cluster::FrameRecord record{frame.state.frame, frame.state.timeS, millisecondsSince(frameStart), {}};
            for (const cluster::RankMessage& r : ranks) {
                stopRequested = stopRequested || r.report.closeRequested;
                record.ranks.push_back(r.report);
                navigationEvents.insert(navigationEvents.end(), r.events.begin(), r.events.end());
            }
            split->observe(ranks);
            if (!session.options.quiet)
                std::printf("%s\n", stats.frameLine(record).c_str());
            if (session.options.verbose)
                std::printf("  %s\n", session.renderer->frameLog().c_str());
            wallStatus.frame = record.frame;
            stats.add(std::move(record));
        }

        // 5. A screenshot or a movie frame: every rank sends its screens, the master writes the wall.
        if (frame.state.gatherWall) {
            io::Image canvas;
            const int status = gatherWallImage(session, world, canvas);
            if (world.isMaster()) {
                writeScreenshots(session, canvas, status, screenshots);
                if (movie)
                    writeMovieFrame(session, *movie, canvas, status, frame.state, stopRequested);
            }
            screenshots.clear();
        }
        world.setPhase(cluster::RankPhase::Broadcast, frame.state.frame);
    }
    if (recorder) {
        try {
            recorder->write();
        } catch (const std::exception& e) {
            session.recordError = std::string("--record-path: ") + e.what();
        }
    }
    return stats;
}

} // namespace aurorawall::app
