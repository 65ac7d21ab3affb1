#include "app/frame_loop.h"

#include "app/band_frame.h"
#include "app/band_split.h"
#include "app/command_outputs.h"
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
#include "io/png.h"
#include "wall/tile_rays.h"

#include <algorithm>
#include <filesystem>
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
                if (session.web) // GET /screenshots/NAME serves it, NAME as asked
                    session.web->addScreenshot(
                        std::filesystem::path(shot.path).lexically_relative(session.options.outDir).generic_string(),
                        shot.path);
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


// The master's own state across frames: its clock and camera, the band split, the input and the
// commands it serves, and the files it writes as the frames go.
struct MasterState {
    MasterState(WallSession& session, const cluster::MpiWorld& world)
        : clock(clockSettings(session), session.scene.camera, session.exposure),
          split(session.bands, world.size(), session.balanced, session.options.balanceBy),
          navigation(session.scene.planetRadiusKm),
          wallFacts{session.scene.planetRadiusKm,
                    session.dataDir + "/config/scenes",
                    session.options.outDir},
          outputs(session.options.sceneFile, clockSettings(session).timeStepS, session.toneMap)
    {
        if (session.control)
            commandChannels.add(*session.control);
        if (session.web) {
            commandChannels.add(session.web->commands());
            outputs.onRecorded = [&web = *session.web](const std::string& name, const std::string& file) {
                web.addRecording(name, file); // GET /recordings/NAME serves it
            };
            outputs.onMovie = [&web = *session.web](const CommandOutputs::MovieNews& news) {
                web.showMovie(news.name, news.folder, news.running, news.error); // GET /movies/NAME, /status
            };
        }
        if (!session.options.movieDir.empty())
            movie.emplace(session.options.movieDir, session.options.movieExr, session.toneMap);
        if (!session.options.recordPath.empty()) {
            const cluster::ClockSettings c = clockSettings(session);
            recorder.emplace(session.options.recordPath, session.options.sceneFile, c.startTimeS, c.timeStepS);
        }
    }

    cluster::MasterClock clock;
    BandSplit split;
    Navigation navigation;
    std::vector<cluster::InputEvent> navigationEvents; // every rank's, gathered with the last frame
    bool hudShown = false;                             // H in any window toggles it
    gl::GamepadState gamepadBefore;
    bool stopRequested = false;
    bool previewDue = false; // this frame's wall goes to the browser console
    control::WallStatus wallStatus;
    std::optional<common::SteadyClock::time_point> lastScreenshot; // when the wall was last gathered for screenshots
    control::WallFacts wallFacts;
    std::vector<control::ScreenshotRequest> screenshots;
    control::PresetLoader presets;
    control::ChannelSet commandChannels; // the control port's clients, the browser's requests
    CommandOutputs outputs;              // record start|stop, movie start|stop
    std::vector<control::OutputRequest> outputRequests; // this frame's, carried out once it is decided
    std::optional<MovieWriter> movie;
    std::optional<PathRecorder> recorder;
    common::SteadyClock::time_point lastRecordWrite = common::SteadyClock::now();
};

// One frame in four phases: the master decides it (input, commands, clock) and broadcasts it; every
// rank draws its bands and exchanges them; windows present and flip together; the master observes
// (the reports, statistics, the wall for screenshots, movie and previews).
class FrameLoop {
public:
    FrameLoop(WallSession& session, const cluster::MpiWorld& world)
        : session_(session), world_(world), bandCount_(session.bands.size()),
          bands_(session.wall, session.bands, world.rank(), session.balanced),
          stats_(pixelsPerFrame(session.wall), componentNames(session.scene)),
          message_(cluster::frameMessageBytes(bandCount_))
    {
        if (world.isMaster()) {
            master_.emplace(session, world);
            const std::string& file = session.options.statsFile;
            if (file.size() > 4 && file.compare(file.size() - 4, 4, ".csv") == 0)
                stats_.streamCsv(file, size_t(world.size()));
        }
    }

    cluster::FrameStats run()
    {
        while (true) {
            const auto frameStart = common::SteadyClock::now();
            const cluster::FrameMessage frame = decide(frameStart);
            world_.setPhase(cluster::RankPhase::Draw, frame.state.frame);
            if (frame.state.quit) {
                if (master_)
                    for (const control::ScreenshotRequest& shot : master_->screenshots)
                        master_->commandChannels.answer(shot.client,
                                                        "error screenshot " + shot.path + ": the wall is quitting");
                break;
            }
            cluster::RankMessage mine = draw(frame);
            present(frame, mine);
            observe(frame, mine, frameStart);
            if (frame.state.gatherWall)
                gatherWall(frame);
            world_.setPhase(cluster::RankPhase::Broadcast, frame.state.frame);
        }
        if (master_ && master_->recorder)
            writeRecording();
        if (master_)
            master_->outputs.finish(master_->commandChannels);
        return std::move(stats_);
    }

private:
    static std::vector<std::string> componentNames(const scene::Scene& scene)
    {
        std::vector<std::string> names;
        for (const scene::Component* c : scene.components())
            names.push_back(c->name());
        return names;
    }

    // 1. The master flies the camera by the window events of the last frame, carries out the remote
    // control's commands and decides the frame; one broadcast tells every rank.
    cluster::FrameMessage decide(common::SteadyClock::time_point frameStart)
    {
        if (master_) {
            MasterState& m = *master_;
            const double lastFrameS = std::chrono::duration<double>(frameStart - previousFrameStart_).count();
            if (!stats_.records().empty()) // over the last frame: drawing, gathering, commands
                m.wallStatus.fps = 1.0 / lastFrameS;
            if (m.lastScreenshot)
                m.wallStatus.sinceScreenshotS = std::chrono::duration<double>(frameStart - *m.lastScreenshot).count();
            steer(stats_.records().empty() ? 0.0 : lastFrameS);
            cluster::FrameState state = m.clock.next(m.stopRequested);
            m.outputs.decide(m.outputRequests, state, m.commandChannels, frameStart);
            m.outputRequests.clear();
            m.wallStatus.recording = m.outputs.recording();
            m.wallStatus.movie = m.outputs.movie();
            m.previewDue = session_.web && session_.web->previewWanted(); // only while a browser watches
            state.gatherWall = !m.screenshots.empty() || m.movie.has_value() || m.outputs.movieWanted() ||
                               session_.console != nullptr || m.previewDue;
            if (m.recorder && !state.quit)
                record(state, frameStart);
            std::vector<std::string> hud;
            if (m.hudShown)
                hud = hudFor(m.clock, stats_, m.wallStatus.fps, session_.scene.planetRadiusKm);
            message_ = cluster::packFrameMessage({state, m.split.next(), {}, hud}, bandCount_);
        }
        previousFrameStart_ = frameStart;
        world_.broadcast(message_);
        return cluster::unpackFrameMessage(message_, bandCount_);
    }

    // The master's input: keys and pointer of every window, the gamepad, the commands.
    void steer(double lastFrameS)
    {
        MasterState& m = *master_;
        for (const cluster::InputEvent& e : m.navigationEvents)
            if (e.type == gl::InputEvent::KeyPressed && e.code == 'H')
                m.hudShown = !m.hudShown;
        if (!m.navigationEvents.empty())
            m.clock.setCamera(m.navigation.apply(m.clock.camera(), m.navigationEvents));
        m.navigationEvents.clear();
        flyByGamepad(*session_.context, m.clock, m.navigation, m.gamepadBefore, lastFrameS);
        if (m.commandChannels.empty())
            return;
        const control::FrameRequests requests =
            control::serveCommands(m.commandChannels, m.clock, m.wallStatus, m.wallFacts, m.presets);
        m.stopRequested = m.stopRequested || requests.quit;
        m.screenshots = requests.screenshots;
        m.outputRequests = requests.outputs;
        if (requests.orbit == control::OrbitRequest::Start)
            m.navigation.orbit(requests.pivotKm);
        else if (requests.orbit == control::OrbitRequest::Stop)
            m.navigation.stopOrbit();
    }

    // The frame's camera into the recorded flight, written as it goes, whole and atomically, at most
    // once a second: a run that fails or is stopped loses at most its last second of flight.
    void record(const cluster::FrameState& state, common::SteadyClock::time_point frameStart)
    {
        MasterState& m = *master_;
        m.recorder->add(state);
        if (frameStart - m.lastRecordWrite < std::chrono::seconds(1) || !session_.recordError.empty())
            return;
        writeRecording();
        m.lastRecordWrite = frameStart;
        m.stopRequested = m.stopRequested || !session_.recordError.empty();
    }

    void writeRecording()
    {
        try {
            master_->recorder->write();
        } catch (const std::exception& e) {
            session_.recordError = std::string("--record-path: ") + e.what();
        }
    }

    // 2. Every rank draws its bands and exchanges those drawn away from their screen.
    cluster::RankMessage draw(const cluster::FrameMessage& frame)
    {
        cluster::RankMessage mine;
        cluster::RankReport& report = mine.report;
        report.frame = frame.state.frame;
        report.timeS = frame.state.timeS;
        report.waitMs = common::millisecondsSince(waitStart_);
        const auto start = common::SteadyClock::now();
        const double prepareCpuStart = common::processCpuMilliseconds();
        session_.renderer->setFrame(frame.state);
        report.prepareMs = common::millisecondsSince(start);
        report.prepareCpuMs = common::processCpuMilliseconds() - prepareCpuStart;
        const std::vector<double>& componentMs = session_.renderer->componentFrameMs();
        std::copy_n(componentMs.begin(), std::min<size_t>(componentMs.size(), cluster::kMaxComponents),
                    report.componentMs);
        mine.costs =
            bands_.draw(*session_.renderer, *session_.context, session_.screens, frame.assignment, world_, report);
        return mine;
    }

    // 3. Windows show the screens' targets and flip together: the swap barrier makes every rank wait
    // until all have drawn into their back buffers, so no screen shows the next frame early. The HUD
    // only on the window of the wall's first screen (one copy, where a reader looks first).
    void present(const cluster::FrameMessage& frame, cluster::RankMessage& mine)
    {
        if (!session_.presenter)
            return;
        cluster::RankReport& report = mine.report;
        session_.context->makeCurrent(0);
        session_.presenter->setHud(frame.hud);
        for (ScreenTarget& s : session_.screens)
            session_.presenter->present(*session_.context, s.window, s.target->texture(), *s.triangle, s.screen == 0);
        auto phase = common::SteadyClock::now();
        world_.swapBarrier();
        report.waitMs += common::millisecondsSince(phase);
        phase = common::SteadyClock::now();
        for (ScreenTarget& s : session_.screens)
            session_.context->swapBuffers(s.window);
        session_.context->pollEvents();
        report.closeRequested = session_.context->closeRequested();
        mine.events = windowEvents(*session_.context);
        report.swapMs = common::millisecondsSince(phase);
        session_.context->makeCurrent(0);
    }

    // 4. One gather: the master learns what every rank drew, how long it took, what its bands cost,
    // what was pressed in its windows, and whether to stop (a closed window, a stop signal).
    void observe(const cluster::FrameMessage& frame, cluster::RankMessage& mine, common::SteadyClock::time_point frameStart)
    {
        waitStart_ = common::SteadyClock::now();
        mine.report.stopSignal = stopSignal();
        world_.setPhase(cluster::RankPhase::Gather, frame.state.frame);
        const std::vector<char> gathered = world_.gather(cluster::packRankMessage(mine, bandCount_));
        if (!master_)
            return;
        MasterState& m = *master_;
        const std::vector<cluster::RankMessage> ranks = cluster::unpackRankMessages(gathered, bandCount_);
        cluster::FrameRecord record{frame.state.frame, frame.state.timeS, common::millisecondsSince(frameStart), {}};
        for (const cluster::RankMessage& r : ranks) {
            m.stopRequested = m.stopRequested || r.report.closeRequested || r.report.stopSignal;
            if (r.report.stopSignal && !session_.stoppedBySignal)
                session_.stoppedBySignal = r.report.stopSignal;
            record.ranks.push_back(r.report);
            m.navigationEvents.insert(m.navigationEvents.end(), r.events.begin(), r.events.end());
        }
        m.split.observe(ranks);
        if (!session_.options.quiet)
            std::printf("%s\n", stats_.frameLine(record).c_str());
        if (session_.options.verbose)
            std::printf("  %s\n", session_.renderer->frameLog().c_str());
        m.wallStatus.frame = record.frame;
        if (session_.web)
            session_.web->showRanks(record);
        try {
            stats_.add(std::move(record));
        } catch (const std::exception& e) {
            session_.statsError = e.what();
            m.stopRequested = true;
        }
    }

    // 5. A screenshot, a movie frame or a preview: every rank sends its screens, the master uses the wall.
    void gatherWall(const cluster::FrameMessage& frame)
    {
        io::Image canvas;
        const int status = gatherWallImage(session_, world_, canvas);
        if (!master_)
            return;
        MasterState& m = *master_;
        if (!m.screenshots.empty())
            m.lastScreenshot = common::SteadyClock::now();
        writeScreenshots(session_, m.commandChannels, canvas, status, m.screenshots);
        m.screenshots.clear();
        if (m.movie)
            writeMovieFrame(session_, *m.movie, canvas, status, frame.state, m.stopRequested);
        m.outputs.writeMovieFrame(canvas, status, frame.state, m.commandChannels);
        m.wallStatus.movie = m.outputs.movie(); // a first frame that failed ended it
        if (session_.console && status == 0)
            showConsole(session_, canvas);
        if (m.previewDue && status == 0)
            session_.web->showPreview(std::move(canvas)); // last: the canvas is handed over
    }

    WallSession& session_;
    const cluster::MpiWorld& world_;
    const size_t bandCount_;
    BandFrame bands_;
    cluster::FrameStats stats_;
    std::optional<MasterState> master_; // rank 0 only
    std::vector<char> message_;
    common::SteadyClock::time_point waitStart_ = common::SteadyClock::now(); // from this rank's previous report to this frame's message
    common::SteadyClock::time_point previousFrameStart_ = common::SteadyClock::now();
};

} // namespace

cluster::FrameStats runFrames(WallSession& session, const cluster::MpiWorld& world)
{
    return FrameLoop(session, world).run();
}

} // namespace aurorawall::app
