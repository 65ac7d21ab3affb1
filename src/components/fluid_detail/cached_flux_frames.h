#pragma once
// The fluid_detail flux frames through the on-disk table cache (io/table_cache.h): the simulation
// costs about a second per rank, reading its 4 MB of frames a few milliseconds. The key holds every
// field of the simulation's spec, the frames' byte-format version and the executable's digest.
#include "components/fluid_detail/simulation/curtain_detail.h"

#include <string>
#include <vector>

namespace aurorawall::components::fluid_detail {

struct CachedFluxFrames {
    roles::FluxFrames frames;
    std::string outcome; // io::CachedTable::outcome
};

// The cache key: "fluid_detail flux frames v1" and every spec field (doubles in hexadecimal, exact),
// then the executable's digest.
std::string fluxFramesCacheKey(const simulation::CurtainDetailSpec& spec);

// simulateCurtainDetail(spec), read from `cacheDirectory` when a good file is there, else simulated
// and written there (an empty directory: simulated, not cached). The frames are bit-identical
// either way.
CachedFluxFrames cachedFluxFrames(const simulation::CurtainDetailSpec& spec, const std::string& cacheDirectory);

} // namespace aurorawall::components::fluid_detail
