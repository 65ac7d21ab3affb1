#pragma once
// The control protocol's `status` answer as JSON for the browser console's GET /status, and each
// rank's last frame for its GET /ranks.
#include "cluster/frame_stats.h"

#include <string>
#include <vector>

namespace aurorawall::app::web {

// "ok frame=12 time_s=3.5 ... paused ..." -> {"frame":12,"time_s":3.5,...,"paused":true}: every
// NAME=VALUE a member (a number if VALUE is one, else a string), the word paused or playing the
// member "paused". Throws std::invalid_argument for a line that does not begin with "ok ".
std::string statusJson(const std::string& statusLine);

// A JSON object ("{...}", as statusJson gives) with the string member NAME: VALUE added at its end
// (VALUE escaped: quotes and backslashes, control characters as spaces).
std::string withMember(const std::string& json, const std::string& name, const std::string& value);

// {"frame":F,"imbalance":I,"heartbeat_period_s":P,"ranks":[{"frame":..,"render_ms":..,"wait_ms":..,
// "heartbeat_age_s":..},...]}: the master's frame and each rank's report of it, with each rank's
// seconds since its last heartbeat reached the master (heartbeatAgesS, in rank order; 0 for the
// master) and the heartbeat period in seconds. Without a watchdog (heartbeatAgesS shorter than the
// ranks) the missing ages and the period are null.
std::string ranksJson(const cluster::FrameRecord& record, const std::vector<double>& heartbeatAgesS,
                      double heartbeatPeriodS);

} // namespace aurorawall::app::web
