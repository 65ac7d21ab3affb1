#include "app/frame_loop.h"

#include "app/band_frame.h"
#include "app/band_split.h"
#include "app/control/geographic_camera.h"
#include "app/control/remote_control.h"
#include "app/gamepad.h"
#include "app/hud.h"
#include "app/navigation.h"
#include "app/path_recorder.h"
#include "app/stop_signal.h"
#include "app/wall_output.h"
#include "cluster/frame_message.h"
#include "cluster/master_clock.h"
#include "cluster/rank_message.h"
#include "common/clock.h"
#include "common/data_dir.h"
#include "io/png.h"
#include "wall/tile_rays.h"

#include <algorithm>
#include <map>
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
    c.wallTanHalfFov = wall::tanHalfVerticalFieldOfView(s.wall);
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

// The master writes the gathered wall for each screenshot asked for and answers its client. A file
// asked for several times in the frame is written once (the same picture): a client repeating one
// screenshot in a loop costs one write a frame, not one for each line.
void writeScreenshots(WallSession& session, control::CommandChannel& channel, const io::Image& canvas, int gatherStatus,
                      const std::vector<control::ScreenshotRequest>& screenshots)
{
    std::map<std::string, std::string> answers; // by path
    for (const control::ScreenshotRequest& shot : screenshots) {
        auto [it, first] = answers.try_emplace(shot.path, "ok screenshot " + shot.path);
        if (first) {
            try {
                if (gatherStatus != 0)
                    throw std::runtime_error("the wall could not be read back");
                io::writePng(shot.path, canvas, session.toneMap); // atomic: a temporary name, then renamed
            } catch (const std::exception& e) {
                it->second = "error screenshot " + shot.path + ": " + e.what();
            }
        }
        channel.answer(shot.client, it->second);
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

// The HUD's text for the frame the master has just decided (the clock shows its time and camera),
// with the statistics of the frame before.
std::vector<std::string> hudFor(const cluster::MasterClock& clock, const cluster::FrameStats& stats, double framesPerS,
                                double planetRadiusKm)
{
    HudFacts facts;
    facts.framesPerS = framesPerS;
    if (!stats.records().empty())
        for (const cluster::RankReport& r : stats.records().back().ranks)
            facts.rankRenderMs.push_back(r.renderMs);
    facts.timeS = clock.timeS();
    facts.paused = clock.paused();
    const control::GeographicPose pose = control::poseOf(clock.camera(), planetRadiusKm);
    facts.altitudeKm = pose.altitudeKm;
    facts.latitudeDeg = pose.latitudeDeg;
    facts.longitudeDeg = pose.longitudeDeg;
    return hudLines(facts);
}

// The master flies the camera with the gamepad, if one is connected to its machine.
void flyByGamepad(gl::Context& context, cluster::MasterClock& clock, Navigation& navigation,
                  gl::GamepadState& previous, double frameS)
{
    gl::GamepadState pad;
    if (!context.gamepad(pad))
        return;
    const GamepadMotion motion = gamepadMotion(pad, previous, frameS);
    previous = pad;
    if (motion.togglePause) {
        if (clock.paused())
            clock.play();
        else
            clock.pause();
    }
    const scene::Camera moved = navigation.apply(clock.camera(), motion); // also sets the speed factor
    if (motion.movesCamera())
        clock.setCamera(moved);
}

// The master shows the gathered wall, downsampled, with the HUD in its console window.
void showConsole(WallSession& session, const io::Image& canvas)
{
    ConsoleView& console = *session.console;
    session.context->makeCurrent(console.window);
    console.image->upload(previewTexels(canvas, console.image->width(), console.image->height()));
    session.presenter->present(*session.context, console.window, *console.image, *console.triangle, true);
    session.context->swapBuffers(console.window);
    session.context->makeCurrent(0);
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
    bool hudShown = false;                             // the master's: H in any window toggles it
    gl::GamepadState gamepadBefore;
    if (world.isMaster()) {
        clock.emplace(clockSettings(session), session.scene.camera, session.exposure);
        split.emplace(session.bands, world.size(), session.balanced,
                      session.options.balanceBy);
    }
    BandFrame bands(session.wall, session.bands, world.rank(), session.balanced);
    std::vector<std::string> componentNames;
    for (const scene::Component* c : session.scene.components())
        componentNames.push_back(c->name());
    cluster::FrameStats stats(pixelsPerFrame(session.wall), componentNames);
    const std::string& statsFile = session.options.statsFile;
    if (world.isMaster() && statsFile.size() > 4 && statsFile.compare(statsFile.size() - 4, 4, ".csv") == 0)
        stats.streamCsv(statsFile, size_t(world.size()));
    bool stopRequested = false;
    bool previewDue = false; // the master's: this frame's wall goes to the browser console
    control::WallStatus wallStatus;
    std::optional<SteadyClock::time_point> lastScreenshot; // when the wall was last gathered for screenshots
    const control::WallFacts wallFacts{session.scene.planetRadiusKm,
                                       (session.options.dataDir.empty() ? dataDirectory() : session.options.dataDir) +
                                           "/config/scenes",
                                       session.options.outDir};
    std::vector<control::ScreenshotRequest> screenshots;
    control::PresetLoader presets;
    control::ChannelSet commandChannels; // the master's: the control port's clients, the browser's requests
    if (session.control)
        commandChannels.add(*session.control);
    if (session.web)
        commandChannels.add(session.web->commands());
    std::optional<MovieWriter> movie;
    if (world.isMaster() && !session.options.movieDir.empty())
        movie.emplace(session.options.movieDir, session.options.movieExr, session.toneMap);
    std::optional<PathRecorder> recorder;
    SteadyClock::time_point lastRecordWrite = SteadyClock::now();
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
            const double lastFrameS = std::chrono::duration<double>(frameStart - previousFrameStart).count();
            if (!stats.records().empty()) // over the last frame: drawing, gathering, commands
                wallStatus.fps = 1.0 / lastFrameS;
            if (lastScreenshot)
                wallStatus.sinceScreenshotS = std::chrono::duration<double>(frameStart - *lastScreenshot).count();
            for (const cluster::InputEvent& e : navigationEvents)
                if (e.type == gl::InputEvent::KeyPressed && e.code == 'H')
                    hudShown = !hudShown;
            if (!navigationEvents.empty())
                clock->setCamera(navigation.apply(clock->camera(), navigationEvents));
            navigationEvents.clear();
            flyByGamepad(*session.context, *clock, navigation, gamepadBefore, stats.records().empty() ? 0.0 : lastFrameS);
            if (!commandChannels.empty()) {
                const control::FrameRequests requests =
                    control::serveCommands(commandChannels, *clock, wallStatus, wallFacts, presets);
                stopRequested = stopRequested || requests.quit;
                screenshots = requests.screenshots;
                if (requests.orbit == control::OrbitRequest::Start)
                    navigation.orbit(requests.pivotKm);
                else if (requests.orbit == control::OrbitRequest::Stop)
                    navigation.stopOrbit();
            }
            cluster::FrameState state = clock->next(stopRequested);
            previewDue = session.web && session.web->previewWanted(); // only while a browser watches
            state.gatherWall = !screenshots.empty() || movie.has_value() || session.console != nullptr || previewDue;
            if (recorder && !state.quit) {
                recorder->add(state);
                // Written as it goes, whole and atomically, at most once a second: a run that fails
                // or is stopped loses at most its last second of flight.
                if (frameStart - lastRecordWrite >= std::chrono::seconds(1) && session.recordError.empty()) {
                    try {
                        recorder->write();
                        lastRecordWrite = frameStart;
                    } catch (const std::exception& e) {
                        session.recordError = std::string("--record-path: ") + e.what();
                        stopRequested = true;
                    }
                }
            }
            std::vector<std::string> hud;
            if (hudShown)
                hud = hudFor(*clock, stats, wallStatus.fps, session.scene.planetRadiusKm);
            message = cluster::packFrameMessage({state, split->next(), {}, hud}, bandCount);
        }
        previousFrameStart = frameStart;
        world.broadcast(message);
        const cluster::FrameMessage frame = cluster::unpackFrameMessage(message, bandCount);
        world.setPhase(cluster::RankPhase::Draw, frame.state.frame);
        if (frame.state.quit) {
            for (const control::ScreenshotRequest& shot : screenshots)
                commandChannels.answer(shot.client, "error screenshot " + shot.path + ": the wall is quitting");
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
        const std::vector<double>& componentMs = session.renderer->componentFrameMs();
        std::copy_n(componentMs.begin(), std::min<size_t>(componentMs.size(), cluster::kMaxComponents),
                    report.componentMs);
        mine.costs = bands.draw(*session.renderer, *session.context, session.screens, frame.assignment, world, report);

        // 3. Windows show the screens' targets and flip together: the swap barrier makes every rank
        // wait until all have drawn into their back buffers, so no screen shows the next frame early.
        // The HUD only on the window of the wall's first screen (one copy, where a reader looks first).
        if (session.presenter) {
            session.context->makeCurrent(0);
            session.presenter->setHud(frame.hud);
            for (ScreenTarget& s : session.screens)
                session.presenter->present(*session.context, s.window, s.target->texture(), *s.triangle, s.screen == 0);
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
        report.stopSignal = stopSignal();
        world.setPhase(cluster::RankPhase::Gather, frame.state.frame);
        const std::vector<char> gathered = world.gather(cluster::packRankMessage(mine, bandCount));
        if (world.isMaster()) {
            const std::vector<cluster::RankMessage> ranks = cluster::unpackRankMessages(gathered, bandCount);
            cluster::FrameRecord record{frame.state.frame, frame.state.timeS, millisecondsSince(frameStart), {}};
            for (const cluster::RankMessage& r : ranks) {
                stopRequested = stopRequested || r.report.closeRequested || r.report.stopSignal;
                if (r.report.stopSignal && !session.stoppedBySignal)
                    session.stoppedBySignal = r.report.stopSignal;
                record.ranks.push_back(r.report);
                navigationEvents.insert(navigationEvents.end(), r.events.begin(), r.events.end());
            }
            split->observe(ranks);
            if (!session.options.quiet)
                std::printf("%s\n", stats.frameLine(record).c_str());
            if (session.options.verbose)
                std::printf("  %s\n", session.renderer->frameLog().c_str());
            wallStatus.frame = record.frame;
            if (session.web)
                session.web->showRanks(record);
            try {
                stats.add(std::move(record));
            } catch (const std::exception& e) {
                session.statsError = e.what();
                stopRequested = true;
            }
        }

        // 5. A screenshot or a movie frame: every rank sends its screens, the master writes the wall.
        if (frame.state.gatherWall) {
            io::Image canvas;
            const int status = gatherWallImage(session, world, canvas);
            if (world.isMaster()) {
                if (!screenshots.empty())
                    lastScreenshot = SteadyClock::now();
                writeScreenshots(session, commandChannels, canvas, status, screenshots);
                if (movie)
                    writeMovieFrame(session, *movie, canvas, status, frame.state, stopRequested);
                if (session.console && status == 0)
                    showConsole(session, canvas);
                if (previewDue && status == 0)
                    session.web->showPreview(std::move(canvas)); // last: the canvas is handed over
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
