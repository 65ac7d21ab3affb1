#include "gl/device_order.h"

#include <gtest/gtest.h>

namespace aurorawall::gl {
namespace {

using Order = std::vector<int>;

TEST(DeviceOrder, OneDeviceIsEveryRanksOnly)
{
    for (int rank = 0; rank < 4; ++rank) {
        EXPECT_EQ(deviceOrder({false}, rank), Order{0});
        EXPECT_EQ(deviceOrder({true}, rank), Order{0});
    }
}

// Four GPUs and four ranks on a node: one rank each; the fifth doubles up on the first.
TEST(DeviceOrder, RanksOfANodeSpreadOverItsGpus)
{
    const std::vector<bool> gpus(4, false);
    EXPECT_EQ(deviceOrder(gpus, 0), (Order{0, 1, 2, 3}));
    EXPECT_EQ(deviceOrder(gpus, 1), (Order{1, 2, 3, 0}));
    EXPECT_EQ(deviceOrder(gpus, 3), (Order{3, 0, 1, 2}));
    EXPECT_EQ(deviceOrder(gpus, 4), (Order{0, 1, 2, 3}));
}

// EGL lists Mesa's software device beside the GPUs (here between them): it is tried last by every rank,
// and the GPUs are shared out as if it were not there.
TEST(DeviceOrder, SoftwareDevicesComeLast)
{
    const std::vector<bool> devices{false, true, false};
    EXPECT_EQ(deviceOrder(devices, 0), (Order{0, 2, 1}));
    EXPECT_EQ(deviceOrder(devices, 1), (Order{2, 0, 1}));
    EXPECT_EQ(deviceOrder(devices, 2), (Order{0, 2, 1}));
    EXPECT_EQ(deviceOrder({true, true}, 1), (Order{0, 1}));
}

TEST(DeviceOrder, NoDevicesNoOrder)
{
    EXPECT_TRUE(deviceOrder({}, 3).empty());
}

} // namespace
} // namespace aurorawall::gl
