#pragma once
// printf-style formatting into a string as long as the text needs: no fixed buffer to cut a message
// that holds a path or other text of any length.
#include <string>

namespace aurorawall::common {

std::string formatted(const char* format, ...) __attribute__((format(printf, 1, 2)));

} // namespace aurorawall::common
