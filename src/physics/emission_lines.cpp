#include "physics/emission_lines.h"

namespace aurorawall::physics {
namespace {

// CIE 1931 2° colour-matching values (x̄, ȳ, z̄) at the lines' wavelengths, 427.8, 557.7, 630.0 and 670 nm (CIE 015).
const LineInfo kLines[kLineCount] = {
    {"427.8nm", 427.8, {0.25600, 0.00960, 1.24420}},
    {"557.7nm", 557.7, {0.55625, 0.99862, 0.00464}},
    {"630.0nm", 630.0, {0.64240, 0.26500, 0.00005}},
    {"N2-1PG", 670.0, {0.08740, 0.03200, 0.00000}},
};

} // namespace

const LineInfo& lineInfo(EmissionLine line)
{
    return kLines[static_cast<int>(line)];
}

} // namespace aurorawall::physics
