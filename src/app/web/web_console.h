#pragma once
// The operator's console in a browser (render --web-port, docs/driving.md "Browser console"): an
// HTTP server on the master, on a thread of its own, serving the page from the data directory's
// web/ folder, POST /command, GET /status, GET /presets, GET /preview.png, GET /ranks (each
// rank's last frame: the frame it drew, its render and wait times, the age of its last heartbeat;
// the master's frame and the imbalance), GET /recordings/NAME (a camera path the wall recorded, its
// base scene embedded), GET /screenshots/NAME (a screenshot the wall wrote) and GET /movies/NAME (a
// movie the wall recorded, once stopped, as one zip streamed from its folder).
// It never touches the wall itself: commands and status go through a CommandMailbox that the frame
// loop serves with the control port's lines, and the preview is the last wall the frame loop
// handed over, downsampled and encoded here, on request.
#include "app/control/command_channel.h"
#include "cluster/frame_stats.h"
#include "io/image.h"
#include "io/tone_map.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace aurorawall::app::web {

struct WebSettings {
    std::string bindAddress = "127.0.0.1"; // dotted IPv4 (--control-bind)
    int port = 0;                          // 0: a free port the system picks
    std::string token;                     // non-empty: /command, /status, /preview.png need "Authorization: Bearer TOKEN"
    std::string pageDir;                   // the page, its script and style (DATA/web)
    std::string presetDir;                 // config/scenes: the names GET /presets lists
    io::ToneMap toneMap;                   // the preview's, as wall.png's
    // Each rank's seconds since its last heartbeat reached the master, now (rank order; empty without
    // a watchdog), called by GET /ranks on the server's thread; and the heartbeat period, s.
    std::function<std::vector<double>()> heartbeatAgesS;
    double heartbeatPeriodS = 1.0;
};

class WebConsole {
public:
    static constexpr std::size_t kMaxLineBytes = 1024;   // a command line, as the control port's; longer: 413
    static constexpr std::size_t kMaxBodyBytes = kMaxLineBytes + 2; // the line and its CRLF or LF
    static constexpr double kAnswerTimeoutS = 10.0;      // a command the wall has not answered by then: 503
    static constexpr double kPreviewIntervalS = 0.2;     // the wall is gathered for the preview at most 5 times a second
    static constexpr double kPreviewInterestS = 2.0;     // ... and only while a browser asked for it this recently
    static constexpr int kPreviewWidthPx = 480;          // at most

    // Listens and starts serving. Throws UsageError for a malformed bind address, InputError naming
    // --web-port if it cannot listen.
    explicit WebConsole(WebSettings settings);
    ~WebConsole(); // stops the server; a request still waiting for the wall gets 503
    WebConsole(const WebConsole&) = delete;
    WebConsole& operator=(const WebConsole&) = delete;

    int port() const;
    const std::string& address() const;

    // The frame loop's side, on its thread only:
    // the browser's command lines, served with the control port's (a ChannelSet);
    control::CommandChannel& commands();
    // whether to gather the wall this frame for the preview;
    bool previewWanted() const;
    // the gathered wall (rows top-down, radiance), taken over: downsampled and encoded when asked for;
    void showPreview(io::Image&& canvas);
    // each rank's report of the last frame, for GET /ranks (ranksJson, with the heartbeats' ages
    // at the time of the request: they grow while a rank is silent and the frame loop waits for it).
    void showRanks(const cluster::FrameRecord& record);
    // a file the wall has recorded (`record start NAME`), for GET /recordings/NAME: only such files
    // are served.
    void addRecording(const std::string& name, const std::string& file);
    // a screenshot the wall has written (`screenshot NAME`), for GET /screenshots/NAME, the same way.
    void addScreenshot(const std::string& name, const std::string& file);
    // a movie's course (`movie start NAME`, its first frame written; a frame that failed; `movie
    // stop`), for GET /movies/NAME (served once stopped; refused with 409 while it runs) and for
    // GET /status, which carries a running movie's failure as "movie_error".
    void showMovie(const std::string& name, const std::string& folder, bool running, const std::string& error);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace aurorawall::app::web
