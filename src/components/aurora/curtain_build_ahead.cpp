#include "components/aurora/curtain_build_ahead.h"

namespace aurorawall::components::aurora {

CurtainBuildAhead::~CurtainBuildAhead()
{
    if (pending_.valid())
        pending_.wait();
}

void CurtainBuildAhead::start(std::vector<CurtainState> states)
{
    if (pending_.valid())
        pending_.wait();
    pendingControlPoints_ = controlPointsOf(states);
    pending_ = std::async(std::launch::async,
                          [&model = model_, states = std::move(states)] { return buildCurtains(model, states); });
}

std::optional<CurtainBuild> CurtainBuildAhead::take(const ControlPoints& controlPoints)
{
    if (!pending_.valid())
        return std::nullopt;
    if (pendingControlPoints_ != controlPoints) {
        // A wrong prediction: dropped unread, so that an error of its build is not reported either.
        pending_.wait();
        pending_ = {};
        return std::nullopt;
    }
    return pending_.get();
}

} // namespace aurorawall::components::aurora
