#include "components/aurora/curtain_build_ahead.h"

namespace aurorawall::components::aurora {

namespace {

void finish(std::future<CurtainBuild>& build)
{
    if (build.valid())
        build.wait();
}

} // namespace

CurtainBuildAhead::~CurtainBuildAhead()
{
    finish(pending_);
    finish(dropped_);
}

void CurtainBuildAhead::start(std::vector<CurtainState> states)
{
    finish(pending_);
    finish(dropped_);
    pendingControlPoints_ = controlPointsOf(states);
    pending_ = std::async(std::launch::async,
                          [&model = model_, builder = builder_, states = std::move(states)] {
                              return buildCurtains(model, states, builder);
                          });
}

std::optional<CurtainBuild> CurtainBuildAhead::take(const ControlPoints& controlPoints)
{
    if (pending_.valid() && pendingControlPoints_ != controlPoints) {
        // A wrong prediction: dropped unread, so that an error of its build is not reported either.
        dropped_ = std::move(pending_);
        return std::nullopt;
    }
    return takeStarted();
}

std::optional<CurtainBuild> CurtainBuildAhead::takeStarted()
{
    if (!pending_.valid())
        return std::nullopt;
    return pending_.get();
}

} // namespace aurorawall::components::aurora
