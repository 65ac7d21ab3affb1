#pragma once
// Builds the curtains of a predicted next frame on a worker thread while this frame draws. The
// build is buildCurtains of the predicted states, so when the next frame's control points are
// exactly the predicted ones it holds the same bytes as a build on the frame's own thread.
#include "components/aurora/curtain_build.h"

#include <future>
#include <optional>
#include <vector>

namespace aurorawall::components::aurora {

class CurtainBuildAhead {
public:
    CurtainBuildAhead(const CurtainModel& model, MapBuilder builder) : model_(model), builder_(builder) {}
    CurtainBuildAhead(const CurtainBuildAhead&) = delete;
    CurtainBuildAhead& operator=(const CurtainBuildAhead&) = delete;
    ~CurtainBuildAhead();

    // Starts building the curtains of these states (after any build started before has finished).
    void start(std::vector<CurtainState> states);
    // The started build if its control points are exactly these, waiting for it to finish; otherwise
    // nothing, at once: a wrong prediction is dropped unread and left to finish on its thread while
    // the caller builds the right curtains (start and the destructor wait for it).
    std::optional<CurtainBuild> take(const ControlPoints& controlPoints);
    // The started build whatever its control points, waiting for it to finish (nothing if none was
    // started or it was taken): for an upload ahead of the frame it predicts.
    std::optional<CurtainBuild> takeStarted();

private:
    const CurtainModel& model_;
    const MapBuilder builder_;
    std::future<CurtainBuild> pending_;
    std::future<CurtainBuild> dropped_; // a wrong prediction still finishing
    ControlPoints pendingControlPoints_;
};

} // namespace aurorawall::components::aurora
