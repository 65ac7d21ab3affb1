#include "app/command_outputs.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace aurorawall::app {

namespace {

std::string seconds(double t)
{
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", t); // the double itself, as the recording holds it
    return text;
}

} // namespace

CommandOutputs::CommandOutputs(std::string sceneFile, double timeStepS, io::ToneMap toneMap)
    : sceneFile_(std::move(sceneFile)), timeStepS_(timeStepS), toneMap_(toneMap)
{
}

void CommandOutputs::decide(const std::vector<control::OutputRequest>& requests, const cluster::FrameState& state,
                            control::CommandChannel& channel, common::SteadyClock::time_point now)
{
    for (const control::OutputRequest& r : requests) {
        switch (r.kind) {
        case control::CommandKind::RecordStart: startRecording(r, state, channel, now); break;
        case control::CommandKind::RecordStop:
            if (recording_)
                stopRecording(r, channel);
            else // its start, asked in this frame, failed
                channel.answer(r.client, "error record stop: no recording runs (its start failed)");
            break;
        case control::CommandKind::MovieStart: startMovie(r, channel); break;
        case control::CommandKind::MovieStop:
            if (movie_)
                stopMovie(r, channel);
            else
                channel.answer(r.client, "error movie stop: no movie runs (its start failed)");
            break;
        default: break;
        }
    }
    if (!recording_ || state.quit)
        return;
    Recording& rec = *recording_;
    rec.recorder.add(state); // the start's frame again: its key replaced by the same camera
    if (now - rec.lastWrite < std::chrono::seconds(1))
        return;
    rec.lastWrite = now;
    try {
        rec.recorder.write();
        rec.error.clear();
    } catch (const std::exception& e) {
        if (rec.error.empty()) // once; retried every second
            std::fprintf(stderr, "aurorawall render: record: %s (retrying every second; the wall goes on)\n", e.what());
        rec.error = e.what();
    }
}

// The recording starts from this frame: written at once, so that a folder that cannot take it is
// answered now. Replayed as a scene, it starts at this frame's time.
void CommandOutputs::startRecording(const control::OutputRequest& request, const cluster::FrameState& state,
                                    control::CommandChannel& channel, common::SteadyClock::time_point now)
{
    Recording rec{request.path, PathRecorder(request.path, sceneFile_, state.timeS, timeStepS_), now, ""};
    rec.recorder.add(state);
    try {
        rec.recorder.write();
    } catch (const std::exception& e) {
        channel.answer(request.client, "error record start " + request.name + ": " + e.what());
        return;
    }
    recording_ = std::move(rec);
    if (onRecorded)
        onRecorded(request.name, request.path);
    channel.answer(request.client, "ok record start " + request.path);
}

// The last write; the answer names what the file holds, so that a client can replay it (`preset
// FILE`, then `time FROM`).
void CommandOutputs::stopRecording(const control::OutputRequest& request, control::CommandChannel& channel)
{
    Recording rec = std::move(*recording_);
    recording_.reset();
    try {
        rec.recorder.write();
    } catch (const std::exception& e) {
        channel.answer(request.client, "error record stop: " + std::string(e.what()) + " (the recording ended)");
        return;
    }
    const std::vector<RecordedCamera>& cameras = rec.recorder.cameras();
    channel.answer(request.client, "ok record stop " + rec.file + " keys=" + std::to_string(cameras.size()) +
                                       " from_s=" + seconds(cameras.front().timeS) +
                                       " to_s=" + seconds(cameras.back().timeS));
}

// The folder is made if missing (its parent exists: control::insideOutputFolder); the first frame
// gathered answers the start.
void CommandOutputs::startMovie(const control::OutputRequest& request, control::CommandChannel& channel)
{
    std::error_code error;
    std::filesystem::create_directory(request.path, error);
    if (error) {
        channel.answer(request.client, "error movie start " + request.name + ": " + request.path + ": " + error.message());
        return;
    }
    movie_.emplace(
        Movie{request.path, MovieWriter(request.path, request.exr, toneMap_), request.client, 0, "", request.name});
}

void CommandOutputs::stopMovie(const control::OutputRequest& request, control::CommandChannel& channel)
{
    Movie movie = std::move(*movie_);
    movie_.reset();
    if (movie.starter)
        channel.answer(*movie.starter, "error movie start: stopped before its first frame");
    else if (onMovie)
        onMovie({movie.name, movie.folder, false, movie.error});
    if (!movie.error.empty())
        return channel.answer(request.client, "error movie stop: " + movie.error + "; the movie ended with " +
                                                  std::to_string(movie.frames) + " frames");
    channel.answer(request.client, "ok movie stop " + movie.folder + " frames=" + std::to_string(movie.frames));
}

void CommandOutputs::writeMovieFrame(const io::Image& canvas, int gatherStatus, const cluster::FrameState& state,
                                     control::CommandChannel& channel)
{
    if (!movieWanted())
        return;
    Movie& movie = *movie_;
    try {
        if (gatherStatus != 0)
            throw std::runtime_error("the wall could not be read back");
        movie.writer.write(canvas, state);
        ++movie.frames;
    } catch (const std::exception& e) {
        movie.error = "frame " + std::to_string(state.frame) + " into " + movie.folder + ": " + e.what();
    }
    if (movie.starter) { // the first frame: the start is answered, and a failure ends the movie
        channel.answer(*movie.starter, movie.error.empty() ? "ok movie start " + movie.folder
                                                          : "error movie start: " + movie.error);
        if (!movie.error.empty()) {
            movie_.reset();
        } else {
            movie.starter.reset();
            if (onMovie)
                onMovie({movie.name, movie.folder, true, ""});
        }
        return;
    }
    if (movie.error.empty())
        return;
    if (onMovie)
        onMovie({movie.name, movie.folder, true, movie.error});
    std::fprintf(stderr, "aurorawall render: movie: %s (no more frames; the wall goes on)\n", movie.error.c_str());
}

void CommandOutputs::finish(control::CommandChannel& channel)
{
    if (movie_ && movie_->starter)
        channel.answer(*movie_->starter, "error movie start: the wall is quitting");
    if (!recording_)
        return;
    try {
        recording_->recorder.write();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "aurorawall render: record: %s\n", e.what());
    }
}

} // namespace aurorawall::app
