#pragma once
// Numbers typed by people (CSV fields, protocol words, option lists) read as decimal only:
// strtod alone would also take hexadecimal ("0x10"), "inf", "nan", leading blanks, and stop quietly
// at a NUL inside the text.
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>

namespace aurorawall::common {

// An optional sign, digits with an optional point (digits on at least one side), an optional exponent.
// A scan, not std::regex: libstdc++'s regex recurses per character and overflows the stack on long text.
inline bool isDecimalNumber(const std::string& text)
{
    size_t i = 0;
    const auto digits = [&] {
        const size_t start = i;
        while (i < text.size() && text[i] >= '0' && text[i] <= '9')
            ++i;
        return i - start;
    };
    if (i < text.size() && (text[i] == '+' || text[i] == '-'))
        ++i;
    size_t mantissa = digits();
    if (i < text.size() && text[i] == '.') {
        ++i;
        mantissa += digits();
    }
    if (mantissa == 0)
        return false;
    if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
        ++i;
        if (i < text.size() && (text[i] == '+' || text[i] == '-'))
            ++i;
        if (digits() == 0)
            return false;
    }
    return i == text.size();
}

// The value of a decimal number that is finite in double; nothing otherwise.
inline std::optional<double> finiteDecimal(const std::string& text)
{
    if (!isDecimalNumber(text))
        return std::nullopt;
    const double value = std::strtod(text.c_str(), nullptr);
    return std::isfinite(value) ? std::optional<double>(value) : std::nullopt;
}

} // namespace aurorawall::common
