#pragma once
// `record start|stop` and `movie start|stop` on the master (docs/driving.md, "Recording from the
// console"): a camera path recording and a movie that commands start and stop while the wall runs,
// beside (and independent of) those of --record-path and --movie, in the same formats. Unlike those, a
// file that cannot be written never stops the wall: the command is answered with an error, a failure
// in between is printed once and answered by the stop.
#include "app/control/command_channel.h"
#include "app/control/remote_control.h"
#include "app/path_recorder.h"
#include "app/wall_output.h"
#include "cluster/frame_state.h"
#include "common/clock.h"
#include "io/image.h"
#include "io/tone_map.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace aurorawall::app {

class CommandOutputs {
public:
    // sceneFile: the played scene, the recordings' base; timeStepS: the clock's (--dt or the scene's);
    // toneMap: the movie's PNGs', as wall.png's.
    CommandOutputs(std::string sceneFile, double timeStepS, io::ToneMap toneMap);

    // Told of every recording once its first write has succeeded: the name as given, its file.
    std::function<void(const std::string& name, const std::string& file)> onRecorded;

    // A movie's course, as the browser console shows it: running once its first frame is written,
    // with an error once a frame could not be (no more frames are written), not running once stopped.
    struct MovieNews {
        std::string name;   // as given to `movie start`: relative to the output folder
        std::string folder; // its path
        bool running = false;
        std::string error;  // the frame that could not be written, else ""
    };
    std::function<void(const MovieNews&)> onMovie;

    // At the frame the master has just decided: carries out this frame's requests in order (a recording
    // starts with this frame's camera, written at once, and is answered; a stop writes it a last time
    // and is answered; a movie starts with this frame, answered once written), then adds the frame's
    // camera to the running recording, written whole at most once a second.
    void decide(const std::vector<control::OutputRequest>& requests, const cluster::FrameState& state,
                control::CommandChannel& channel, common::SteadyClock::time_point now);

    // Whether the wall is to be gathered this frame for the movie.
    bool movieWanted() const { return movie_ && movie_->error.empty(); }

    // The frame's gathered wall into the movie (gatherStatus != 0: it could not be read back).
    void writeMovieFrame(const io::Image& canvas, int gatherStatus, const cluster::FrameState& state,
                         control::CommandChannel& channel);

    // The run ends: the recording written a last time (a failure printed), a movie start not yet
    // answered refused.
    void finish(control::CommandChannel& channel);

    // What runs, for `status` refusals: the recording's file, the movie's folder ("" if none).
    std::string recording() const { return recording_ ? recording_->file : ""; }
    std::string movie() const { return movie_ ? movie_->folder : ""; }

private:
    struct Recording {
        std::string file;
        PathRecorder recorder;
        common::SteadyClock::time_point lastWrite;
        std::string error; // the last write's failure, "" once written
    };
    struct Movie {
        std::string folder;
        MovieWriter writer;
        std::optional<std::uint64_t> starter; // the client of `movie start`, until its first frame
        std::size_t frames = 0;
        std::string error; // the frame that could not be written: no more frames
        std::string name;  // as given
    };

    void startRecording(const control::OutputRequest& request, const cluster::FrameState& state,
                        control::CommandChannel& channel, common::SteadyClock::time_point now);
    void stopRecording(const control::OutputRequest& request, control::CommandChannel& channel);
    void startMovie(const control::OutputRequest& request, control::CommandChannel& channel);
    void stopMovie(const control::OutputRequest& request, control::CommandChannel& channel);

    std::string sceneFile_;
    double timeStepS_;
    io::ToneMap toneMap_;
    std::optional<Recording> recording_;
    std::optional<Movie> movie_;
};

} // namespace aurorawall::app
