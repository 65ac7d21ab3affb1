#include "gl/device_order.h"

#include <cstddef>

namespace aurorawall::gl {

std::vector<int> deviceOrder(const std::vector<bool>& isSoftware, int nodeRank)
{
    std::vector<int> hardware, software;
    for (int i = 0; i < static_cast<int>(isSoftware.size()); ++i)
        (isSoftware[static_cast<std::size_t>(i)] ? software : hardware).push_back(i);
    std::vector<int> order;
    const int count = static_cast<int>(hardware.size());
    const int first = count > 0 ? (nodeRank % count + count) % count : 0;
    for (int k = 0; k < count; ++k)
        order.push_back(hardware[static_cast<std::size_t>((first + k) % count)]);
    order.insert(order.end(), software.begin(), software.end());
    return order;
}

} // namespace aurorawall::gl
