#pragma once
// TOML basic strings as aurorawall writes them (recorded paths): quoted, with only " and \ escaped.
#include <optional>
#include <string>

namespace aurorawall::config {

// "s" with every " and \ escaped by a backslash.
std::string tomlBasicString(const std::string& s);

// The value of a basic string holding only the escapes \" and \\ (what tomlBasicString writes);
// nullopt for any other text.
std::optional<std::string> tomlBasicStringValue(const std::string& text);

} // namespace aurorawall::config
