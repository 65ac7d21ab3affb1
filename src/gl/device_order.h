#pragma once
// Which GL device a rank draws on when its node has several. A display-wall node often drives its
// screens from two to four GPUs, one rank each: the ranks on one node spread over its hardware devices
// by their index on the node, so that none doubles up on a GPU while another GPU idles. Software
// devices (Mesa's llvmpipe, which EGL also lists as a device) come last, as a fallback.
#include <vector>

namespace aurorawall::gl {

// The order in which the rank with index nodeRank among its node's ranks tries the devices, by their
// index in `isSoftware` (true: a software device): the hardware devices first, from the one numbered
// nodeRank mod their count, round; then the software ones in their order.
std::vector<int> deviceOrder(const std::vector<bool>& isSoftware, int nodeRank);

} // namespace aurorawall::gl
