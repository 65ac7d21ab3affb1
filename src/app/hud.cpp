#include "app/hud.h"

#include "cluster/frame_message.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace aurorawall::app {

namespace {

template <typename... Args>
std::string format(const char* pattern, Args... args)
{
    char line[cluster::kHudColumns + 1];
    std::snprintf(line, sizeof line, pattern, args...);
    return line;
}

} // namespace

std::vector<std::string> hudLines(const HudFacts& f)
{
    std::vector<std::string> lines;
    // Times up to 1e15 s are accepted: beyond 1e9 s in exponent form, so that the line keeps "PAUSED".
    const char* first = std::abs(f.timeS) < 1e9 ? "FPS %.1f  T %.2f S%s" : "FPS %.1f  T %.4E S%s";
    lines.push_back(format(first, f.framesPerS, f.timeS, f.paused ? "  PAUSED" : ""));
    lines.push_back(format("ALT %.3f KM", f.altitudeKm));
    lines.push_back(format("LAT %.3f LON %.3f", f.latitudeDeg, f.longitudeDeg));
    const std::vector<double>& ms = f.rankRenderMs;
    const double slowest = ms.empty() ? 0.0 : *std::max_element(ms.begin(), ms.end());
    const double mean = ms.empty() ? 0.0 : std::accumulate(ms.begin(), ms.end(), 0.0) / double(ms.size());
    lines.push_back(format("IMBALANCE %.2f (MAX/MEAN)", mean > 0.0 ? slowest / mean : 1.0));
    // One line per rank while they fit; the last line counts those that do not.
    const size_t room = cluster::kHudLines - lines.size();
    const size_t shown = ms.size() <= room ? ms.size() : room - 1;
    for (size_t r = 0; r < shown; ++r) {
        const int cells = slowest > 0.0 ? static_cast<int>(std::lround(kHudBarCells * ms[r] / slowest)) : 0;
        lines.push_back(format("R%-3zu", r) + std::string(cells, '#') + std::string(kHudBarCells - cells, ' ') +
                        format(" %.1f MS", ms[r]));
    }
    if (shown < ms.size())
        lines.push_back(format("+%zu RANKS NOT SHOWN", ms.size() - shown));
    return lines;
}

} // namespace aurorawall::app
