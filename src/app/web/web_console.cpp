#include "app/web/web_console.h"

#include "app/console_view.h"
#include "app/control/control_server.h"
#include "app/wall_output.h"
#include "app/web/command_mailbox.h"
#include "app/web/downloads.h"
#include "app/web/movie_archive.h"
#include "app/web/status_json.h"
#include "common/input_error.h"
#include "io/png.h"

#include <httplib.h>


#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <mutex>
#include <thread>
#include <vector>

namespace aurorawall::app::web {

namespace {

double secondsNow()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void reply(httplib::Response& res, int status, const std::string& line)
{
    res.status = status;
    res.set_content(line + "\n", "text/plain; charset=utf-8");
}

// What httplib refuses by itself.
std::string refusal(int status)
{
    switch (status) {
    case 400: return " malformed request";
    case 404: return " no such page";
    case 405: return " method not allowed";
    case 411: return " length required (send the command with a Content-Length, not chunked)";
    case 413: return " request too large (a command is one line of at most 1024 bytes)";
    case 414: return " request line too long";
    default: return "";
    }
}

// A route the console serves: its method and its path (a folder's prefix ending in '/', for the names in it).
struct Route {
    std::string method;
    std::string path;
};

// Before a request's body is read: a path holding a NUL (%00, which would cut the file name short of the
// extension that names its type) or a Content-Length that is not one whole number (httplib reads
// "abc" as 0 and the first of two) is malformed (400); a route asked with another method is refused
// (405, naming the one it takes), and so is a chunked body (411), which httplib would read whole, past
// the 1024-byte limit.
httplib::Server::HandlerResponse refuseBeforeTheBody(const std::vector<Route>& routes, const httplib::Request& req,
                                                     httplib::Response& res)
{
    const std::string length = req.get_header_value("Content-Length");
    const bool lengthMalformed = req.get_header_value_count("Content-Length") > 1 ||
                                 (req.has_header("Content-Length") &&
                                  (length.empty() || length.find_first_not_of("0123456789") != std::string::npos));
    if (req.path.find('\0') != std::string::npos || lengthMalformed) {
        res.set_header("Connection", "close");
        reply(res, 400, "error 400" + refusal(400));
        return httplib::Server::HandlerResponse::Handled;
    }
    if (req.has_header("Transfer-Encoding")) {
        res.set_header("Connection", "close");
        reply(res, 411, "error 411" + refusal(411));
        return httplib::Server::HandlerResponse::Handled;
    }
    for (const Route& route : routes) {
        const bool matches = route.path.back() == '/' ? req.path.rfind(route.path, 0) == 0 : req.path == route.path;
        const bool allowed = req.method == route.method || (req.method == "HEAD" && route.method == "GET");
        if (matches && !allowed) {
            res.set_header("Allow", route.method);
            res.set_header("Connection", "close");
            reply(res, 405, "error 405" + refusal(405) + " (" + route.path + " takes " + route.method + ")");
            return httplib::Server::HandlerResponse::Handled;
        }
    }
    return httplib::Server::HandlerResponse::Unhandled;
}

} // namespace

struct WebConsole::Impl {
    WebSettings settings;
    httplib::Server server;
    CommandMailbox mailbox;
    std::thread thread;
    int port = 0;
    std::atomic<bool> stopping{false}; // the wall quits: a movie still being sent is cut short
    std::vector<Route> routes;         // every route served, for 405 (set before the server starts)

    // The preview: handed over by the frame loop, encoded by the first request that finds it new.
    std::atomic<double> previewAskedS{-1e9}; // when a browser last asked for it (steady clock)
    double previewShownS = -1e9;             // the frame loop's: when it last handed one over
    std::mutex previewMutex;
    std::shared_ptr<const io::Image> canvas; // the last wall handed over, not yet encoded
    std::shared_ptr<const std::string> png;  // the last encoded preview
    std::optional<cluster::FrameRecord> lastFrame; // GET /ranks: the last frame's reports (previewMutex)
    std::map<std::string, std::string> recordings;  // GET /recordings/NAME: name as recorded -> file (previewMutex)
    std::map<std::string, std::string> screenshots; // GET /screenshots/NAME: name as asked -> file (previewMutex)
    struct Movie {
        std::string folder;
        bool running = false;
        std::string error;
    };
    std::map<std::string, Movie> movies; // GET /movies/NAME: name as given -> its folder (previewMutex)
    std::string movieError;              // the running movie's failure, for GET /status (previewMutex)

    bool authorized(const httplib::Request& req, httplib::Response& res) const
    {
        if (settings.token.empty() || req.get_header_value("Authorization") == "Bearer " + settings.token)
            return true;
        res.set_header("WWW-Authenticate", "Bearer realm=\"aurorawall\""); // RFC 6750
        reply(res, 401, "error authentication required: send the header 'Authorization: Bearer SECRET'");
        return false;
    }

    void command(const httplib::Request& req, httplib::Response& res)
    {
        std::string line = req.body;
        while (!line.empty() && (line.back() == '\n' || line.back() == '\r'))
            line.pop_back();
        if (line.find('\n') != std::string::npos)
            return reply(res, 400, "error one command per request");
        if (line.size() > kMaxLineBytes)
            return reply(res, 413, "error 413" + refusal(413));
        const std::optional<std::string> answer = mailbox.ask(line, kAnswerTimeoutS);
        if (!answer)
            return reply(res, 503, "error the wall did not answer");
        reply(res, 200, *answer);
    }

    void status(httplib::Response& res)
    {
        const std::optional<std::string> answer = mailbox.ask("status", kAnswerTimeoutS);
        if (!answer)
            return reply(res, 503, "error the wall did not answer");
        std::string json = statusJson(*answer);
        {
            std::lock_guard<std::mutex> lock(previewMutex);
            if (!movieError.empty()) // the page shows it; the stop answers it too
                json = withMember(json, "movie_error", movieError);
        }
        res.set_content(json, "application/json");
    }

    void presets(httplib::Response& res) const
    {
        std::vector<std::string> names;
        std::error_code error;
        for (const auto& entry : std::filesystem::directory_iterator(settings.presetDir, error))
            if (entry.path().extension() == ".toml")
                names.push_back(entry.path().stem().string());
        std::sort(names.begin(), names.end());
        std::string json = "[";
        for (const std::string& name : names)
            json += (json.size() > 1 ? ",\"" : "\"") + name + "\""; // file names of the data directory: no quotes
        res.set_content(json + "]", "application/json");
    }

    // The last frame's reports with each rank's heartbeat age now ({} before the first frame).
    void ranks(httplib::Response& res)
    {
        std::optional<cluster::FrameRecord> frame;
        {
            std::lock_guard<std::mutex> lock(previewMutex);
            frame = lastFrame;
        }
        const std::vector<double> ages =
            frame && settings.heartbeatAgesS ? settings.heartbeatAgesS() : std::vector<double>{};
        res.set_content(frame ? ranksJson(*frame, ages, settings.heartbeatPeriodS) : "{}", "application/json");
    }

    // A file the wall wrote, looked up by the name it was asked for under: no other file can be
    // named, so no path leaves the output folder. Empty if there is none.
    std::string written(const std::map<std::string, std::string>& table, const std::string& name,
                        std::string& file)
    {
        {
            std::lock_guard<std::mutex> lock(previewMutex);
            const auto it = table.find(name);
            if (it != table.end())
                file = it->second;
        }
        std::ifstream in(file, std::ios::binary);
        if (file.empty() || !in)
            return "";
        return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    }

    // The file name a download is saved under: the name's last part, quotable.
    static std::string savedName(const std::string& name)
    {
        std::string base = std::filesystem::path(name).filename().string();
        std::replace_if(base.begin(), base.end(),
                        [](char c) { return c == '"' || c == '\\' || static_cast<unsigned char>(c) < 0x20; }, '_');
        return base;
    }

    // A download: saved as `fileName` (already made quotable), never cached.
    static void attachmentHeaders(httplib::Response& res, const std::string& fileName)
    {
        res.set_header("Content-Disposition", "attachment; filename=\"" + fileName + "\"");
        res.set_header("Cache-Control", "no-store");
    }

    static void attach(httplib::Response& res, const std::string& name, std::string&& bytes, const char* type)
    {
        attachmentHeaders(res, savedName(name));
        res.set_content(std::move(bytes), type);
    }

    // A recorded camera path with its base scene embedded, so that the copy replays on any machine.
    void recording(const std::string& name, httplib::Response& res)
    {
        std::string file;
        const std::string text = written(recordings, name, file);
        if (text.empty())
            return reply(res, 404, "error 404 no such recording (only the paths this wall recorded)");
        std::string embedded;
        try {
            embedded = recordingForDownload(text, std::filesystem::path(file).parent_path().string());
        } catch (const std::exception& e) {
            return reply(res, 500, "error recording " + name + ": " + e.what());
        }
        attach(res, name, std::move(embedded), "application/toml");
    }

    void screenshot(const std::string& name, httplib::Response& res)
    {
        std::string file;
        std::string bytes = written(screenshots, name, file);
        if (bytes.empty())
            return reply(res, 404, "error 404 no such screenshot (only the files this wall wrote for `screenshot`)");
        attach(res, name, std::move(bytes), "image/png");
    }

    // A stopped movie as NAME.zip (its frames and frames.csv under NAME/), streamed from its folder:
    // never held in memory. A failure on the way cuts the transfer short (no final chunk, no zip
    // directory), so the client sees an incomplete download, never a short zip taken for whole; so
    // does the wall's quit (a long download does not hold it up).
    void movie(const std::string& name, httplib::Response& res)
    {
        std::optional<Movie> found;
        {
            std::lock_guard<std::mutex> lock(previewMutex);
            const auto it = movies.find(name);
            if (it != movies.end())
                found = it->second;
        }
        if (!found)
            return reply(res, 404, "error 404 no such movie (only the movies this wall recorded with `movie start`)");
        if (found->running)
            return reply(res, 409, "error 409 movie " + name + " is still recording (`movie stop` first)");
        std::vector<MovieFile> files;
        try {
            files = movieFiles(found->folder);
        } catch (const std::exception& e) {
            return reply(res, 410, "error 410 movie " + name + ": " + e.what());
        }
        const bool holdsFrames =
            std::any_of(files.begin(), files.end(), [](const MovieFile& f) { return f.name != MovieWriter::kFramesList; });
        if (!holdsFrames)
            return reply(res, 410, "error 410 movie " + name + ": its folder holds no frames any more");
        const std::string base = savedName(name);
        attachmentHeaders(res, base + ".zip");
        res.set_chunked_content_provider(
            "application/zip", [this, folder = found->folder, files, base](std::size_t, httplib::DataSink& sink) {
                const auto send = [this, &sink](const char* data, std::size_t n) {
                    return !stopping && sink.write(data, n);
                };
                const std::string error = writeMovieZip(folder, files, base, send);
                if (error == kClientGone)
                    return false; // a cancelled download, a client too slow, or the wall's quit
                if (!error.empty()) {
                    std::fprintf(stderr, "aurorawall render: GET /movies/%s: %s (the download was cut short)\n",
                                 base.c_str(), error.c_str());
                    return false;
                }
                sink.done();
                return true;
            });
    }

    void preview(httplib::Response& res)
    {
        previewAskedS = secondsNow();
        std::shared_ptr<const io::Image> fresh;
        std::shared_ptr<const std::string> encoded;
        {
            std::lock_guard<std::mutex> lock(previewMutex);
            fresh = std::move(canvas);
            canvas.reset();
            encoded = png;
        }
        if (fresh) { // downsampled and encoded here, off the frame loop
            const int width = std::min(kPreviewWidthPx, fresh->width);
            const int height = std::max(1, int(std::lround(double(width) * fresh->height / fresh->width)));
            const io::Image small = io::imageFromGlReadback(width, height, previewTexels(*fresh, width, height));
            const std::vector<std::uint8_t> bytes = io::encodePng(small, settings.toneMap);
            encoded = std::make_shared<const std::string>(bytes.begin(), bytes.end());
            std::lock_guard<std::mutex> lock(previewMutex);
            png = encoded;
        }
        if (!encoded)
            return reply(res, 503, "error no preview yet (the wall is gathered within a frame or two)");
        res.set_header("Cache-Control", "no-store");
        res.set_content(*encoded, "image/png");
    }
};

WebConsole::WebConsole(WebSettings settings) : impl_(std::make_unique<Impl>())
{
    Impl& w = *impl_;
    w.settings = std::move(settings);
    control::bindAddressOf(w.settings.bindAddress);
    httplib::Server& s = w.server;
    // Bounded work per client: 8 threads, short timeouts, small bodies (413 beyond).
    s.new_task_queue = [] { return new httplib::ThreadPool(8); };
    s.set_read_timeout(2, 0);
    s.set_write_timeout(2, 0);
    s.set_keep_alive_timeout(2);
    s.set_payload_max_length(kMaxBodyBytes);
    s.set_pre_routing_handler([&w](const httplib::Request& req, httplib::Response& res) {
        return refuseBeforeTheBody(w.routes, req, res);
    });
    // SO_REUSEADDR only: httplib's default adds SO_REUSEPORT, with which a second wall listened on a port in
    // use and the two shared its requests.
    s.set_socket_options([](socket_t sock) {
        int yes = 1;
        setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    });
    // The page, its script and style; httplib refuses paths leaving the folder (404).
    if (!s.set_mount_point("/", w.settings.pageDir))
        throw common::InputError("--web-port: the page's folder " + w.settings.pageDir + " cannot be read");
    // Each route, served to an authorized request only; a folder's route takes the name after it.
    using Serve = std::function<void(const httplib::Request&, httplib::Response&)>;
    const auto route = [&w, &s](const std::string& method, const std::string& path, Serve serve) {
        w.routes.push_back({method, path});
        const auto handler = [&w, serve](const httplib::Request& req, httplib::Response& res) {
            if (w.authorized(req, res))
                serve(req, res);
        };
        const std::string pattern = path.back() == '/' ? path + "(.+)" : path;
        method == "POST" ? s.Post(pattern, handler) : s.Get(pattern, handler);
    };
    route("POST", "/command", [&w](const httplib::Request& req, httplib::Response& res) { w.command(req, res); });
    route("GET", "/status", [&w](const httplib::Request&, httplib::Response& res) { w.status(res); });
    route("GET", "/presets", [&w](const httplib::Request&, httplib::Response& res) { w.presets(res); });
    route("GET", "/ranks", [&w](const httplib::Request&, httplib::Response& res) { w.ranks(res); });
    route("GET", "/recordings/",
          [&w](const httplib::Request& req, httplib::Response& res) { w.recording(req.matches[1], res); });
    route("GET", "/screenshots/",
          [&w](const httplib::Request& req, httplib::Response& res) { w.screenshot(req.matches[1], res); });
    route("GET", "/movies/", [&w](const httplib::Request& req, httplib::Response& res) { w.movie(req.matches[1], res); });
    route("GET", "/preview.png", [&w](const httplib::Request&, httplib::Response& res) { w.preview(res); });
    // httplib's own refusals (400 malformed, 404, 413 too large) get one line saying so.
    s.set_error_handler([](const httplib::Request&, httplib::Response& res) {
        if (res.body.empty())
            reply(res, res.status, "error " + std::to_string(res.status) + refusal(res.status));
    });
    s.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr error) {
        std::string reason = "unknown";
        try {
            std::rethrow_exception(error);
        } catch (const std::exception& e) {
            reason = e.what();
        } catch (...) {
        }
        reply(res, 500, "error " + reason);
    });
    w.port = w.settings.port == 0 ? s.bind_to_any_port(w.settings.bindAddress)
                                  : (s.bind_to_port(w.settings.bindAddress, w.settings.port) ? w.settings.port : -1);
    if (w.port < 0)
        throw common::InputError("--web-port " + std::to_string(w.settings.port) + ": cannot listen on " +
                         w.settings.bindAddress + ":" + std::to_string(w.settings.port) + " (in use?)");
    w.thread = std::thread([&s] { s.listen_after_bind(); });
}

WebConsole::~WebConsole()
{
    impl_->mailbox.close(); // first: a handler waiting for the wall returns, so the server can stop
    impl_->stopping = true;  // and a movie being sent ends
    impl_->server.stop();
    impl_->thread.join();
}

void WebConsole::showRanks(const cluster::FrameRecord& record)
{
    cluster::FrameRecord copy = record;
    std::lock_guard<std::mutex> lock(impl_->previewMutex);
    impl_->lastFrame = std::move(copy);
}

void WebConsole::addRecording(const std::string& name, const std::string& file)
{
    std::lock_guard<std::mutex> lock(impl_->previewMutex);
    impl_->recordings[name] = file;
}

void WebConsole::addScreenshot(const std::string& name, const std::string& file)
{
    std::lock_guard<std::mutex> lock(impl_->previewMutex);
    impl_->screenshots[name] = file;
}

void WebConsole::showMovie(const std::string& name, const std::string& folder, bool running, const std::string& error)
{
    std::lock_guard<std::mutex> lock(impl_->previewMutex);
    impl_->movies[name] = {folder, running, error};
    impl_->movieError = running ? error : "";
}

int WebConsole::port() const { return impl_->port; }
const std::string& WebConsole::address() const { return impl_->settings.bindAddress; }
control::CommandChannel& WebConsole::commands() { return impl_->mailbox; }

bool WebConsole::previewWanted() const
{
    const double now = secondsNow();
    return now - impl_->previewAskedS < kPreviewInterestS && now - impl_->previewShownS >= kPreviewIntervalS;
}

void WebConsole::showPreview(io::Image&& canvas)
{
    impl_->previewShownS = secondsNow();
    auto taken = std::make_shared<const io::Image>(std::move(canvas));
    std::lock_guard<std::mutex> lock(impl_->previewMutex);
    impl_->canvas = std::move(taken);
}

} // namespace aurorawall::app::web
