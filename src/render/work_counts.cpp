#include "render/work_counts.h"

#include <algorithm>
#include <stdexcept>

namespace aurorawall::render {

WorkSummary summarizeWork(const std::vector<float>& counts, glm::ivec2 size)
{
    if (size.x <= 0 || size.y <= 0 || counts.size() != std::size_t(size.x) * std::size_t(size.y) * kWorkQuantities)
        throw std::invalid_argument("summarizeWork: the counts do not fit the size");
    WorkSummary summary;
    const auto at = [&](int x, int y, int q) { return double(counts[(std::size_t(y) * size.x + x) * kWorkQuantities + q]); };
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x)
            for (int q = 0; q < kWorkQuantities; ++q)
                summary.meanPerPixel[q] += at(x, y, q);
    int blocks = 0;
    for (int by = 0; by < size.y; by += kWarpHeight)
        for (int bx = 0; bx < size.x; bx += kWarpWidth) {
            ++blocks;
            for (int q = 0; q < kWorkQuantities; ++q) {
                double largest = 0.0;
                for (int y = by; y < std::min(by + kWarpHeight, size.y); ++y)
                    for (int x = bx; x < std::min(bx + kWarpWidth, size.x); ++x)
                        largest = std::max(largest, at(x, y, q));
                summary.meanBlockMax[q] += largest;
            }
        }
    for (int q = 0; q < kWorkQuantities; ++q) {
        summary.meanPerPixel[q] /= double(size.x) * double(size.y);
        summary.meanBlockMax[q] /= double(blocks);
    }
    return summary;
}

} // namespace aurorawall::render
