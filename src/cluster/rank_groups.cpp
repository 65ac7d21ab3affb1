#include "cluster/rank_groups.h"

namespace aurorawall::cluster {

namespace {

// "ranks 0-2, 5" or "rank 7": the ranks (ascending) as runs of consecutive numbers.
std::string runsOf(const std::vector<int>& ranks)
{
    std::string text = ranks.size() == 1 ? "rank " : "ranks ";
    for (size_t i = 0; i < ranks.size();) {
        size_t j = i;
        while (j + 1 < ranks.size() && ranks[j + 1] == ranks[j] + 1)
            ++j;
        text += (i > 0 ? ", " : "") + std::to_string(ranks[i]) + (j > i ? "-" + std::to_string(ranks[j]) : "");
        i = j + 1;
    }
    return text;
}

} // namespace

std::string ranksByValue(const std::vector<std::string>& valueOfRank)
{
    std::vector<std::string> values;
    std::vector<std::vector<int>> ranks;
    for (int r = 0; r < static_cast<int>(valueOfRank.size()); ++r) {
        size_t k = 0;
        while (k < values.size() && values[k] != valueOfRank[static_cast<size_t>(r)])
            ++k;
        if (k == values.size()) {
            values.push_back(valueOfRank[static_cast<size_t>(r)]);
            ranks.emplace_back();
        }
        ranks[k].push_back(r);
    }
    std::string line;
    for (size_t k = 0; k < values.size(); ++k)
        line += (k > 0 ? "; " : "") + values[k] + " (" + runsOf(ranks[k]) + ")";
    return line;
}

} // namespace aurorawall::cluster
