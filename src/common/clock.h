#pragma once
// Timing for the frame statistics: wall time, and the CPU time of the whole process (every
// thread, llvmpipe's rendering threads included), which measures a rank's own work even when
// ranks share cores.
#include <chrono>
#include <ctime>

namespace aurorawall::common {

using SteadyClock = std::chrono::steady_clock;

inline double millisecondsSince(SteadyClock::time_point start)
{
    return std::chrono::duration<double, std::milli>(SteadyClock::now() - start).count();
}

inline double processCpuMilliseconds()
{
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

} // namespace aurorawall::common
