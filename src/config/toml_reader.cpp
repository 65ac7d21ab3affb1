#include "config/toml_reader.h"

#include "common/input_error.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>

namespace aurorawall::config {

namespace {

// toml11 formats errors over several lines with a source excerpt; keep the problem and its hint.
std::string oneLine(const std::string& what)
{
    std::istringstream lines(what);
    std::string first, line, hint;
    std::getline(lines, first);
    while (std::getline(lines, line))
        if (auto at = line.find("^---"); at != std::string::npos)
            hint = line.substr(at + 4);
    if (first.rfind("[error] ", 0) == 0)
        first = first.substr(8);
    // toml11's own function names ("toml::parse_value: ", "parse_ml_basic_string: ") mean nothing to a user.
    while (first.rfind("toml::", 0) == 0 || first.rfind("parse_", 0) == 0) {
        const auto colon = first.find(": ");
        if (colon == std::string::npos)
            break;
        first = first.substr(colon + 2);
    }
    while (!hint.empty() && hint.front() == ' ')
        hint.erase(hint.begin());
    return hint.empty() ? first : first + " (" + hint + ")";
}

} // namespace

namespace {

// An open bracket of the text: '[' (an array or a table header) or '{' (an inline table), with the
// elements an array has so far (its commas, and whether something follows the last).
struct OpenBracket {
    char bracket;
    int line;
    std::size_t commas = 0;
    bool pending = false;
};

// Puts a line break after every comma of an array (outside strings and comments, and not in inline
// tables, where TOML allows none), keeping the file's line of each resulting line. Refuses an array of
// more than kMaxTomlArrayElements elements, or more than kMaxTomlFileArrayElements in all, nesting
// deeper than kMaxTomlNesting, a key of more than kMaxTomlKeyParts parts and an inline table of more
// than kMaxTomlInlineTableEntries entries.
class ArrayBreaker {
public:
    ArrayBreaker(const std::string& path, const std::string& text) : path_(path), text_(text)
    {
        out_.reserve(text.size() + text.size() / 8);
    }

    std::string run(std::vector<int>& lines)
    {
        lines_.assign(1, 1);
        for (i_ = 0; i_ < text_.size(); ++i_) {
            const char c = text_[i_];
            out_ += c;
            if (c == '\n')
                newLine();
            else if (in_ == In::Code)
                code(c);
            else if (in_ != In::Comment)
                string(c);
        }
        lines = std::move(lines_);
        return std::move(out_);
    }

private:
    enum class In { Code, Comment, Basic, Literal, MultiBasic, MultiLiteral };

    void newLine()
    {
        lines_.push_back(++line_);
        startKey(open_.empty()); // a line outside brackets starts with a key or a table header
        if (in_ == In::Comment || in_ == In::Basic || in_ == In::Literal)
            in_ = In::Code;
    }

    // Inside a string: its end (a triple quote copied whole), or an escaped character copied with its backslash.
    void string(char c)
    {
        const bool basic = in_ == In::Basic || in_ == In::MultiBasic;
        const bool multi = in_ == In::MultiBasic || in_ == In::MultiLiteral;
        const char quote = basic ? '"' : '\'';
        if (basic && c == '\\' && i_ + 1 < text_.size() && text_[i_ + 1] != '\n') {
            out_ += text_[++i_];
        } else if (!multi && c == quote) {
            in_ = In::Code;
        } else if (multi && text_.compare(i_, 3, std::string(3, quote)) == 0) {
            out_ += std::string(2, quote);
            i_ += 2;
            in_ = In::Code;
        }
    }

    // A key starts (at a line's start, or an inline table's entry) or, with false, a value does.
    void startKey(bool key)
    {
        inKey_ = key;
        keyDots_ = 0;
    }

    void code(char c)
    {
        if (inKey_ && c == '.' && ++keyDots_ >= kMaxTomlKeyParts)
            throw common::inputError(path_, line_, "a key of more than " + std::to_string(kMaxTomlKeyParts) +
                                                       " dotted parts, the most a config key may have");
        if (c == '=')
            startKey(false);
        if (c == '#') {
            in_ = In::Comment;
        } else if (c == '"' || c == '\'') {
            element();
            const bool triple = text_.compare(i_, 3, std::string(3, c)) == 0;
            in_ = c == '"' ? (triple ? In::MultiBasic : In::Basic) : (triple ? In::MultiLiteral : In::Literal);
            if (triple) {
                out_ += std::string(2, c);
                i_ += 2;
            }
        } else if (c == '[' || c == '{') {
            element();
            if (open_.size() >= kMaxTomlNesting)
                throw common::inputError(path_, line_, "arrays and inline tables nested more than " +
                                                           std::to_string(kMaxTomlNesting) +
                                                           " deep, the most a config file may have");
            open_.push_back({c, line_});
            if (c == '{')
                startKey(true);
        } else if ((c == ']' || c == '}') && !open_.empty()) {
            if (open_.back().bracket == '[')
                closeArray(open_.back());
            open_.pop_back();
        } else if (c == ',' && !open_.empty() && open_.back().bracket == '{') {
            if (++open_.back().commas >= kMaxTomlInlineTableEntries)
                throw common::inputError(path_, open_.back().line, "an inline table of more than " +
                                                                       std::to_string(kMaxTomlInlineTableEntries) +
                                                                       " entries, the most a config table may have");
            startKey(true);
        } else if (c == ',' && !open_.empty() && open_.back().bracket == '[') {
            checkLength(open_.back(), ++open_.back().commas);
            open_.back().pending = false;
            out_ += '\n';
            lines_.push_back(line_);
        } else if (c != ',' && c != ' ' && c != '\t' && c != '\r') {
            element();
        }
    }

    // Something other than a comma or a closing bracket starts (or continues) an element.
    void element()
    {
        if (!open_.empty())
            open_.back().pending = true;
    }

    void checkLength(const OpenBracket& array, std::size_t elements) const
    {
        if (elements > kMaxTomlArrayElements)
            throw common::inputError(path_, array.line, "an array of more than " + std::to_string(kMaxTomlArrayElements) +
                                                    " elements, the most a config array may have");
    }

    void closeArray(const OpenBracket& array)
    {
        const std::size_t elements = array.commas + (array.pending ? 1 : 0);
        checkLength(array, elements);
        fileElements_ += elements;
        if (fileElements_ > kMaxTomlFileArrayElements)
            throw common::inputError(path_, array.line, "more than " + std::to_string(kMaxTomlFileArrayElements) +
                                                    " array elements in the file, the most a config file may hold");
    }

    const std::string& path_;
    const std::string& text_;
    std::string out_;
    std::vector<int> lines_;
    std::vector<OpenBracket> open_;
    std::size_t fileElements_ = 0;
    std::size_t i_ = 0;
    int line_ = 1;
    In in_ = In::Code;
    bool inKey_ = true; // the file's first line starts with a key or a table header
    std::size_t keyDots_ = 0;
};

} // namespace

TomlFile parseTomlFile(const std::string& path)
{
    if (std::filesystem::exists(path) && !std::filesystem::is_regular_file(path))
        throw common::inputError(path, 0, "not a regular file (a config file is a TOML text file)");
    if (!std::filesystem::is_regular_file(path))
        throw common::inputError(path, 0, "scene file not found");
    std::error_code error;
    const std::uintmax_t bytes = std::filesystem::file_size(path, error);
    if (!error && bytes > kMaxTomlFileBytes)
        throw common::inputError(path, 0, "the file has " + std::to_string(bytes) + " bytes, more than the " +
                                      std::to_string(kMaxTomlFileBytes >> 20) + " MiB a config file may have");
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    if (!in || (bytes > 0 && !(text << in.rdbuf())))
        throw common::inputError(path, 0, "cannot read the file");
    auto lines = std::make_shared<std::vector<int>>();
    std::istringstream broken(ArrayBreaker(path, text.str()).run(*lines));
    const auto fileLine = [&lines](std::size_t parsed) {
        return parsed >= 1 && parsed <= lines->size() ? (*lines)[parsed - 1] : int(parsed);
    };
    try {
        return {toml::parse<toml::discard_comments>(broken, path), lines};
    } catch (const toml::exception& e) {
        throw common::inputError(path, fileLine(e.location().line()), oneLine(e.what()));
    } catch (const std::exception& e) {
        throw common::inputError(path, 0, e.what());
    }
}

TableReader::TableReader(const TomlValue& table, std::string file, std::string tableName, LineMap lines)
    : table_(table), file_(std::move(file)), name_(std::move(tableName)), lines_(std::move(lines))
{
    if (!table_.is_table())
        throw common::inputError(file_, line(), "'" + name_ + "' must be a table");
}

int TableReader::fileLine(const TomlValue& value) const
{
    const std::size_t parsed = value.location().line();
    return lines_ && parsed >= 1 && parsed <= lines_->size() ? (*lines_)[parsed - 1] : static_cast<int>(parsed);
}

int TableReader::line() const { return fileLine(table_); }

int TableReader::lineOf(const std::string& key) const
{
    return has(key) ? fileLine(table_.as_table().at(key)) : line();
}

std::string TableReader::qualified(const std::string& key) const
{
    return name_.empty() ? key : name_ + "." + key;
}

void TableReader::fail(const std::string& key, const std::string& problem) const
{
    throw common::inputError(file_, lineOf(key), qualified(key) + ": " + problem);
}

bool TableReader::has(const std::string& key) const { return table_.as_table().count(key) != 0; }

// Whether a and b differ by at most one edit (a letter changed, added or left out) once case is ignored:
// the misspellings a missing key most likely came from.
static bool nearlyEqual(const std::string& a, const std::string& b)
{
    auto lower = [](std::string s) {
        std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
        return s;
    };
    const std::string x = lower(a), y = lower(b);
    const std::string& shorter = x.size() <= y.size() ? x : y;
    const std::string& longer = x.size() <= y.size() ? y : x;
    if (longer.size() - shorter.size() > 1)
        return false;
    std::size_t front = 0;
    while (front < shorter.size() && shorter[front] == longer[front])
        ++front;
    std::size_t back = 0;
    while (back < shorter.size() - front && shorter[shorter.size() - 1 - back] == longer[longer.size() - 1 - back])
        ++back;
    return front + back + 1 >= longer.size();
}

const TomlValue& TableReader::at(const std::string& key) const
{
    if (!has(key)) {
        for (const auto& [given, value] : table_.as_table())
            if (nearlyEqual(given, key))
                throw common::inputError(file_, fileLine(value),
                                         "missing key '" + qualified(key) + "' (misspelt as '" +
                                             common::echoedInput(given) + "'?)");
        throw common::inputError(file_, line(), "missing key '" + qualified(key) + "'");
    }
    read_.insert(key);
    return table_.as_table().at(key);
}

// toml11 reads an integer literal beyond 64 bits as the nearest limit, which no key allows: say so rather
// than echo a number the file does not hold.
static std::string givenInteger(const TomlValue& v)
{
    const auto x = v.as_integer();
    if (x == std::numeric_limits<decltype(x)>::max() || x == std::numeric_limits<decltype(x)>::min())
        return "an integer beyond 64 bits";
    return std::to_string(x);
}

static bool toNumber(const TomlValue& v, double& out)
{
    if (v.is_floating()) { out = v.as_floating(); return true; }
    if (v.is_integer()) { out = static_cast<double>(v.as_integer()); return true; }
    return false;
}

double TableReader::boundedNumber(const std::string& key, double lo, double hi, bool loIncluded) const
{
    double x = 0;
    const TomlValue& v = at(key);
    if (!toNumber(v, x))
        fail(key, "expected a number");
    if (!std::isfinite(x) || (loIncluded ? x < lo : x <= lo) || x > hi) {
        std::ostringstream s;
        s << "must be a finite number in " << (loIncluded ? "[" : "(") << lo << ", " << hi << "] (got ";
        if (v.is_integer())
            s << givenInteger(v) << ")";
        else
            s << x << ")";
        fail(key, s.str());
    }
    return x;
}

double TableReader::number(const std::string& key, double lo, double hi) const
{
    return boundedNumber(key, lo, hi, true);
}

double TableReader::number(const std::string& key, double lo, double hi, double fallback) const
{
    return has(key) ? number(key, lo, hi) : fallback;
}

double TableReader::numberAbove(const std::string& key, double lo, double hi) const
{
    return boundedNumber(key, lo, hi, false);
}

double TableReader::numberAbove(const std::string& key, double lo, double hi, double fallback) const
{
    return has(key) ? numberAbove(key, lo, hi) : fallback;
}

// Integers are TOML integers: a float, even 2.0, is not a count of screens or pixels.
static bool toInteger(const TomlValue& v, long long lo, long long hi, long long& out)
{
    if (!v.is_integer() || v.as_integer() < lo || v.as_integer() > hi)
        return false;
    out = v.as_integer();
    return true;
}

static std::string integerProblem(const TomlValue& v, long long lo, long long hi)
{
    if (!v.is_integer())
        return "expected an integer";
    return "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "] (got " + givenInteger(v) +
           ")";
}

int TableReader::integer(const std::string& key, int lo, int hi) const
{
    return static_cast<int>(integer64(key, lo, hi));
}

int TableReader::integer(const std::string& key, int lo, int hi, int fallback) const
{
    return has(key) ? integer(key, lo, hi) : fallback;
}

long long TableReader::integer64(const std::string& key, long long lo, long long hi) const
{
    const TomlValue& v = at(key);
    long long x = 0;
    if (!toInteger(v, lo, hi, x))
        fail(key, integerProblem(v, lo, hi));
    return x;
}

long long TableReader::integer64(const std::string& key, long long lo, long long hi, long long fallback) const
{
    return has(key) ? integer64(key, lo, hi) : fallback;
}

std::vector<int> TableReader::integers(const std::string& key, int lo, int hi) const
{
    const TomlValue& v = at(key);
    if (!v.is_array())
        fail(key, "expected an array of integers");
    std::vector<int> out;
    for (const auto& item : v.as_array()) {
        long long x = 0;
        if (!toInteger(item, lo, hi, x))
            fail(key, "item " + std::to_string(out.size()) + ": " + integerProblem(item, lo, hi));
        out.push_back(static_cast<int>(x));
    }
    return out;
}

std::string TableReader::string(const std::string& key) const
{
    const TomlValue& v = at(key);
    if (!v.is_string())
        fail(key, "expected a string");
    return v.as_string().str;
}

std::string TableReader::string(const std::string& key, const std::string& fallback) const
{
    return has(key) ? string(key) : fallback;
}

int TableReader::choice(const std::string& key, const std::vector<std::string>& words, int fallback) const
{
    if (!has(key))
        return fallback;
    const std::string word = string(key);
    for (size_t i = 0; i < words.size(); ++i)
        if (word == words[i])
            return static_cast<int>(i);
    std::string list;
    for (const std::string& w : words)
        list += (list.empty() ? "\"" : ", \"") + w + "\"";
    fail(key, "must be one of " + list + " (got \"" + common::echoedInput(word) + "\")");
}

std::vector<std::string> TableReader::strings(const std::string& key) const
{
    const TomlValue& v = at(key);
    if (!v.is_array())
        fail(key, "expected an array of strings");
    std::vector<std::string> out;
    for (const auto& item : v.as_array()) {
        if (!item.is_string())
            fail(key, "expected an array of strings");
        out.push_back(item.as_string().str);
    }
    return out;
}

glm::dvec3 TableReader::vector3(const std::string& key, double lo, double hi, glm::dvec3 fallback) const
{
    if (!has(key))
        return fallback;
    const glm::dvec3 v = vector3(key);
    for (int i = 0; i < 3; ++i)
        if (v[i] < lo || v[i] > hi) {
            std::ostringstream s;
            s << "every element must be in [" << lo << ", " << hi << "] (got " << v[i] << ")";
            fail(key, s.str());
        }
    return v;
}

glm::dvec3 TableReader::vector3(const std::string& key) const
{
    const TomlValue& v = at(key);
    glm::dvec3 out;
    if (!v.is_array() || v.as_array().size() != 3)
        fail(key, "expected an array of 3 numbers");
    for (int i = 0; i < 3; ++i)
        if (!toNumber(v.as_array()[i], out[i]) || !std::isfinite(out[i]) || std::abs(out[i]) > 1e12)
            fail(key, "expected an array of 3 finite numbers, each at most 1e12 in size");
    return out;
}

std::vector<glm::dvec2> TableReader::pairs(const std::string& key, glm::dvec2 lo, glm::dvec2 hi) const
{
    const TomlValue& v = at(key);
    if (!v.is_array())
        fail(key, "expected an array of [a, b] pairs");
    std::vector<glm::dvec2> out;
    for (const auto& item : v.as_array()) {
        glm::dvec2 p;
        if (!item.is_array() || item.as_array().size() != 2 || !toNumber(item.as_array()[0], p.x) ||
            !toNumber(item.as_array()[1], p.y))
            fail(key, "expected an array of [a, b] pairs of numbers");
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || p.x < lo.x || p.x > hi.x || p.y < lo.y || p.y > hi.y) {
            std::ostringstream s;
            s << "pair [" << p.x << ", " << p.y << "] is outside [" << lo.x << ", " << hi.x << "] x [" << lo.y
              << ", " << hi.y << "]";
            fail(key, s.str());
        }
        out.push_back(p);
    }
    return out;
}

TableReader TableReader::table(const std::string& key) const
{
    const TomlValue& v = at(key);
    if (!v.is_table())
        fail(key, "expected a table");
    return TableReader(v, file_, qualified(key), lines_);
}

TableReader TableReader::optionalTable(const std::string& key) const
{
    static const TomlValue empty = TomlValue(TomlValue::table_type());
    return has(key) ? table(key) : TableReader(empty, file_, qualified(key), lines_);
}

std::vector<TableReader> TableReader::arrayOfTables(const std::string& key) const
{
    const TomlValue& v = at(key);
    if (!v.is_array())
        fail(key, "expected an array of tables ([[" + qualified(key) + "]])");
    std::vector<TableReader> out;
    for (const auto& item : v.as_array()) {
        if (!item.is_table())
            fail(key, "expected an array of tables ([[" + qualified(key) + "]])");
        out.emplace_back(item, file_, qualified(key), lines_);
    }
    return out;
}

void TableReader::rejectKeysOutside(const std::vector<std::string>& known) const
{
    const std::pair<const std::string, TomlValue>* first = nullptr;
    for (const auto& entry : table_.as_table())
        if (std::find(known.begin(), known.end(), entry.first) == known.end() &&
            (!first || fileLine(entry.second) < fileLine(first->second)))
            first = &entry;
    if (!first)
        return;
    std::string list;
    for (const std::string& k : known)
        list += (list.empty() ? "" : ", ") + k;
    throw common::inputError(file_, fileLine(first->second),
                     "unknown key '" + common::echoedInput(qualified(first->first)) + "'; known keys: " + list);
}

void TableReader::rejectUnknownKeys() const
{
    for (const auto& [key, value] : table_.as_table())
        if (!read_.count(key))
            throw common::inputError(file_, fileLine(value),
                             "unknown key '" + common::echoedInput(qualified(key)) + "'");
}

} // namespace aurorawall::config
