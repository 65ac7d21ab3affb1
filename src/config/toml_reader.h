#pragma once
// Reading a TOML config file (a wall, a scene) with errors that name file, line and key
// (toml11 from Debian). Every table is read through a TableReader, which knows which keys it has
// consumed, so a misspelt key is reported instead of silently ignored.
#include <glm/glm.hpp>
#include <toml.hpp>

#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace aurorawall::config {

using TomlValue = toml::basic_value<toml::discard_comments>;

// The line numbers of a parsed file: parsed line k (1-based) is line lines[k - 1] of the file.
using LineMap = std::shared_ptr<const std::vector<int>>;

struct TomlFile {
    TomlValue root;
    LineMap lines;
};

// The largest file read (a scene or wall file; past it one error line names the file).
constexpr std::size_t kMaxTomlFileBytes = 16u << 20;
// The most elements an inline array may have, and all of a file's inline arrays together (nested
// arrays' elements counted too): toml11 takes about 4 µs a value on the 2-core machine, so a file
// at the limits reads in about half a second, and one past them is refused before it is parsed.
constexpr std::size_t kMaxTomlArrayElements = 16384;
constexpr std::size_t kMaxTomlFileArrayElements = 131072;
// The deepest nesting of arrays and inline tables: toml11 parses them recursively, and about 10,000
// levels overflow the stack, so a file nested deeper is refused before it is parsed.
constexpr std::size_t kMaxTomlNesting = 64;
// The most parts a dotted key or table header may have, and entries an inline table may have: toml11
// takes time growing as the square of either (52 s for an inline table of 20,000 keys, 20 s for a key
// of 40,000 parts), so a file past them is refused before it is parsed.
constexpr std::size_t kMaxTomlKeyParts = 16;
constexpr std::size_t kMaxTomlInlineTableEntries = 256;

// Parses a file; syntax errors become InputError "file:line: problem". Arrays are parsed with a
// line break after each of their commas (toml11 scans a value's whole line for comments, which made
// an array on one line cost the square of its length: 48 s for 40,000 points); the line numbers in
// errors are the file's. Arrays past the limits above are refused with their line before parsing.
TomlFile parseTomlFile(const std::string& path);

class TableReader {
public:
    TableReader(const TomlValue& table, std::string file, std::string tableName, LineMap lines = nullptr);

    bool has(const std::string& key) const;
    // Numbers must be finite and within [lo, hi]; integers are accepted where floats are asked for.
    double number(const std::string& key, double lo, double hi) const;
    double number(const std::string& key, double lo, double hi, double fallback) const;
    // A finite number in (lo, hi]: lo itself excluded, e.g. a size or a distance that must be > 0.
    double numberAbove(const std::string& key, double lo, double hi) const;
    double numberAbove(const std::string& key, double lo, double hi, double fallback) const;
    // A TOML integer (not a float, even 2.0) within [lo, hi].
    int integer(const std::string& key, int lo, int hi) const;
    int integer(const std::string& key, int lo, int hi, int fallback) const;
    // The same for values beyond int's range (a 32-bit seed).
    long long integer64(const std::string& key, long long lo, long long hi) const;
    long long integer64(const std::string& key, long long lo, long long hi, long long fallback) const;
    // An array of TOML integers, each within [lo, hi].
    std::vector<int> integers(const std::string& key, int lo, int hi) const;
    std::string string(const std::string& key) const;
    std::string string(const std::string& key, const std::string& fallback) const;
    std::vector<std::string> strings(const std::string& key) const;
    // One of the given words; returns its index (fallback when the key is absent).
    int choice(const std::string& key, const std::vector<std::string>& words, int fallback) const;
    glm::dvec3 vector3(const std::string& key) const;
    // Each component finite and within [lo, hi]; fallback when the key is absent.
    glm::dvec3 vector3(const std::string& key, double lo, double hi, glm::dvec3 fallback) const;
    // An array of [a, b] pairs, e.g. latitude/longitude control points.
    std::vector<glm::dvec2> pairs(const std::string& key, glm::dvec2 lo, glm::dvec2 hi) const;
    TableReader table(const std::string& key) const;
    // A table that may be left out: then every key takes its default.
    TableReader optionalTable(const std::string& key) const;
    std::vector<TableReader> arrayOfTables(const std::string& key) const;

    // Throws for the first key that was never read (a typo, or a key of a component not listed).
    void rejectUnknownKeys() const;
    // Throws for the first key (in file order) that is not one of known, listing them: called
    // before reading, it reports a typo as itself rather than as the key it should have been.
    void rejectKeysOutside(const std::vector<std::string>& known) const;

    int line() const;
    int lineOf(const std::string& key) const;
    const std::string& file() const { return file_; }
    [[noreturn]] void fail(const std::string& key, const std::string& problem) const;

private:
    const TomlValue& at(const std::string& key) const;
    // A finite number in [lo, hi], or in (lo, hi] when !loIncluded.
    double boundedNumber(const std::string& key, double lo, double hi, bool loIncluded) const;
    std::string qualified(const std::string& key) const;

    int fileLine(const TomlValue& value) const; // the value's line in the file

    const TomlValue& table_;
    std::string file_;
    std::string name_;
    LineMap lines_;
    mutable std::set<std::string> read_;
};

} // namespace aurorawall::config
