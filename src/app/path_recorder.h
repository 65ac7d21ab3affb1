#pragma once
// `render --record-path FILE`: the master keeps the camera of every frame it broadcasts and writes
// them as a scene that derives from the played one ([scene] base) and flies that camera as a keyed
// path, one [[camera.key]] per frame. Numbers are printed with 17 significant digits, which gives
// back every double exactly, so the recorded file plays the same camera at every recorded time
// (scene::CameraPath is exact at its keys; between keys it interpolates). A frame zoomed by its
// path (FrameState::zoom != 1) gets its zoom as a key's `zoom` (a field of view would not read back
// as the same double). A single recorded camera is a plain [camera], which has no zoom; zoomed, it is
// two keys one time step apart (1 s without a step) that hold it.
#include "cluster/frame_state.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace aurorawall::app {

struct RecordedCamera {
    double timeS = 0.0;          // the frame's animation time, s
    glm::dvec3 positionKm{0.0};  // planet frame, km
    glm::dvec3 forward{0.0, 1.0, 0.0};
    glm::dvec3 up{0.0, 0.0, 1.0};
    double zoom = 1.0;           // the frame's zoom (cluster::wallToPlanet)
};

class PathRecorder {
public:
    // file: where the scene goes; baseScene: the played scene file; startTimeS and timeStepS: the
    // clock's, written into [scene] so that the file replays without --start-time or --dt.
    PathRecorder(std::string file, std::string baseScene, double startTimeS, double timeStepS);

    // The camera of a frame. Keys need increasing times: a frame at the last key's time (paused)
    // replaces that key, and a frame at an earlier time (the clock set back) drops the keys from
    // its time on, so the file holds the flight last flown through each time.
    void add(const cluster::FrameState& state);

    const std::vector<RecordedCamera>& cameras() const { return cameras_; }

    // The scene file's text: [camera.key] tables for two or more cameras, a still [camera] for one,
    // no camera (the base scene's) for none.
    std::string text() const;

    // Writes text() atomically (io/atomic_file.h); throws std::runtime_error "FILE: reason".
    void write() const;

private:
    std::string file_;
    std::string baseScene_;
    double startTimeS_;
    double timeStepS_;
    std::vector<RecordedCamera> cameras_;
};

} // namespace aurorawall::app
