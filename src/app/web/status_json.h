#pragma once
// The control protocol's `status` answer as JSON for the browser console's GET /status.
#include <string>

namespace aurorawall::app::web {

// "ok frame=12 time_s=3.5 ... paused ..." -> {"frame":12,"time_s":3.5,...,"paused":true}: every
// NAME=VALUE a member (a number if VALUE is one, else a string), the word paused or playing the
// member "paused". Throws std::invalid_argument for a line that does not begin with "ok ".
std::string statusJson(const std::string& statusLine);

} // namespace aurorawall::app::web
