#include "common/input_error.h"

#include <cstdio>

namespace aurorawall::common {

std::string echoedInput(const std::string& text)
{
    std::size_t kept = text.size();
    if (kept > kEchoedInputBytes) {
        kept = kEchoedInputBytes;
        while (kept > 0 && (static_cast<unsigned char>(text[kept]) & 0xC0) == 0x80) // inside a UTF-8 character
            --kept;
    }
    std::string echoed;
    for (std::size_t i = 0; i < kept; ++i) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (c == '\n') echoed += "\\n";
        else if (c == '\t') echoed += "\\t";
        else if (c == '\r') echoed += "\\r";
        else if (c < 0x20 || c == 0x7F) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\x%02X", c);
            echoed += escaped;
        } else echoed += static_cast<char>(c);
    }
    if (kept < text.size())
        echoed += "… (" + std::to_string(text.size()) + " bytes)";
    return echoed;
}

} // namespace aurorawall::common
