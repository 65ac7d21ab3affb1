#pragma once
// Ranks grouped by something each reports (its GL device, its host), for one line on the master.
#include <string>
#include <vector>

namespace aurorawall::cluster {

// "A (ranks 0-2, 5); B (ranks 3-4)" for valueOfRank = A A A B B A: each value once, in the order of its
// first rank, with its ranks as runs ("rank 7" for one).
std::string ranksByValue(const std::vector<std::string>& valueOfRank);

} // namespace aurorawall::cluster
