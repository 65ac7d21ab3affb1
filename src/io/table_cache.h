#pragma once
// Precomputed tables kept on disk between runs, so that a costly start-up computation (the
// fluid_detail simulation) is done once per input and build. A file holds its key in full, the
// table's bytes and a checksum over both: a file whose checksum, size or key does not match is
// never trusted but rebuilt. One process builds a missing table while the others that want it wait
// (an advisory lock on "<file>.lock"; the ranks of a node share its cores, so building it once is
// faster than building it in each) and then read it. Files are written atomically (temporary name,
// then rename), so where locks are not available, ranks that build the same table at once each rename
// a complete file over the same name: every reader sees one complete file, and all hold the same
// bytes.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace aurorawall::io {

// $XDG_CACHE_HOME/aurorawall, else $HOME/.cache/aurorawall; empty when neither variable is set.
std::string defaultCacheDirectory();

// The running executable's identity for cache keys: FNV-1a (64 bit) of /proc/self/exe as 16 hex
// digits, computed once per process. Any rebuild that changes the code changes it.
const std::string& executableDigest();

// FNV-1a, 64 bit (Fowler, Noll & Vo): offset basis 0xcbf29ce484222325, prime 0x100000001b3.
std::uint64_t fnv1a64(const void* data, std::size_t size, std::uint64_t hash = 0xcbf29ce484222325ull);

struct CachedTable {
    std::vector<char> bytes;
    // For the precomputation log line: "read from cache", "read from cache, built by another
    // process", "built, cached", "cache corrupt, rebuilt", or "built, not cached (reason)".
    std::string outcome;
};

// The table stored under `key` in `directory` (file "<name>-<FNV-1a of key>.table"), or, when there
// is none or it is corrupt, build()'s bytes, then written there (creating the folder); of the files
// of one name the newest 8 are kept, older ones removed. An empty directory means no cache. Failing to read or write the cache is reported in the outcome, never
// thrown; build()'s exceptions propagate.
CachedTable cachedTable(const std::string& directory, const std::string& name, const std::string& key,
                        const std::function<std::vector<char>()>& build);

// The file cachedTable uses for (directory, name, key).
std::string cachedTablePath(const std::string& directory, const std::string& name, const std::string& key);

} // namespace aurorawall::io
