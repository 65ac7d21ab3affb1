#pragma once
// What the tests that sweep a command's options over their ranges share: exact decimal text of a
// double, its neighbours, and the first non-finite number in a command's output.
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace aurorawall::test {

// Decimal text that reads back as exactly this double (17 significant digits).
inline std::string exactly(double value)
{
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

inline double above(double x) { return std::nextafter(x, INFINITY); }
inline double below(double x) { return std::nextafter(x, -INFINITY); }

// The first cell of the output (split at commas and line ends) that reads as a number but is not
// finite, or "" when there is none.
inline std::string nonFiniteCell(const std::string& output)
{
    std::string cell;
    for (std::size_t i = 0; i <= output.size(); ++i) {
        if (i < output.size() && output[i] != ',' && output[i] != '\n') {
            cell += output[i];
            continue;
        }
        char* end = nullptr;
        const double value = std::strtod(cell.c_str(), &end);
        if (!cell.empty() && *end == '\0' && !std::isfinite(value)) return cell;
        cell.clear();
    }
    return "";
}

} // namespace aurorawall::test
