#include "app/airmass_command.h"

#include "cli/command_line.h"
#include "cli/exit_status.h"
#include "physics/atmosphere/airmass.h"
#include "common/decimal_number.h"
#include "common/input_error.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <limits>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace aurorawall::app {

using namespace physics::atmosphere; // the airmass methods

namespace {

// The input's columns, in order; a first line of exactly these names (any case) is a header.
const char* const kFields[] = {"ox", "oy", "oz", "dx", "dy", "dz", "t0", "t1", "H", "R"};
constexpr int kFieldCount = 10;

std::string trimmed(const std::string& text)
{
    size_t first = text.find_first_not_of(" \t\r");
    if (first == std::string::npos) return "";
    size_t last = text.find_last_not_of(" \t\r");
    return text.substr(first, last - first + 1);
}

// The line's comma-separated fields, trimmed (a trailing comma gives a last empty field).
std::vector<std::string> fieldsOf(const std::string& line)
{
    std::vector<std::string> fields;
    size_t begin = 0;
    for (;;) {
        const size_t comma = line.find(',', begin);
        fields.push_back(trimmed(line.substr(begin, comma == std::string::npos ? std::string::npos : comma - begin)));
        if (comma == std::string::npos) return fields;
        begin = comma + 1;
    }
}

bool isHeader(const std::vector<std::string>& fields)
{
    if (fields.size() != kFieldCount) return false;
    for (int i = 0; i < kFieldCount; ++i)
        if (!std::equal(fields[i].begin(), fields[i].end(), kFields[i], kFields[i] + std::strlen(kFields[i]),
                        [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == std::tolower(b); }))
            return false;
    return true;
}

// One CSV line's fields as a ray, or an error message naming the field. Every field must be a finite
// number within float's range (the closed forms run in float32, as the shader does): |value| <= 3.4e38;
// H at least float's smallest positive number, 1.40129846e-45 (printed rounded up, 1.4012985e-45, so that
// the printed bound is accepted; below, H rounds to 0 in float); R >= 0.
std::optional<AirmassRay> parseRay(const std::vector<std::string>& fields, std::string& problem)
{
    if (fields.size() != kFieldCount) {
        problem = "expected 10 comma-separated numbers ox,oy,oz,dx,dy,dz,t0,t1,H,R, got " +
                  std::to_string(fields.size()) + " fields";
        return std::nullopt;
    }
    double values[kFieldCount];
    for (int i = 0; i < kFieldCount; ++i) {
        const std::string name = "field " + std::to_string(i + 1) + " (" + kFields[i] + ")";
        const std::string& text = fields[i];
        const std::optional<double> value = common::finiteDecimal(text);
        if (!value) {
            problem = name + (common::isDecimalNumber(text) ? " is not finite: '" : " is not a number: '") +
                      common::echoedInput(text) + "'";
            return std::nullopt;
        }
        values[i] = *value;
        if (!(std::abs(values[i]) <= std::numeric_limits<float>::max())) {
            problem = name + " must be within float's range, |value| <= 3.40282347e+38 (got '" + common::echoedInput(text) + "')";
            return std::nullopt;
        }
    }
    AirmassRay ray{{values[0], values[1], values[2]}, {values[3], values[4], values[5]},
                   values[6], values[7], values[8], values[9]};
    if (!(ray.scaleHeight >= std::numeric_limits<float>::denorm_min())) {
        problem = "field 9 (H) must be at least 1.4012985e-45 km, float's smallest positive number (got '" + common::echoedInput(fields[8]) + "')";
        return std::nullopt;
    }
    if (ray.planetRadius < 0.0) {
        problem = "field 10 (R) must be >= 0 (got '" + common::echoedInput(fields[9]) + "')";
        return std::nullopt;
    }
    return ray;
}

} // namespace

int runAirmassCommand(int argc, char** argv, std::istream& in, std::ostream& out, std::ostream& err)
{
    return cli::runCommand("airmass", out, err, [&] {
        cli::CommandLine cli(
            "airmass",
            "Usage: aurorawall airmass [--method NAME] < rays.csv\n"
            "Airmass I = integral from t0 to t1 of exp(-(|o + t*d/|d|| - R)/H) dt, in km, for each input line\n"
            "ox,oy,oz,dx,dy,dz,t0,t1,H,R (km; planet centre at the origin; t in km along the unit direction;\n"
            "a first line of these names is a header; blank lines are skipped). Every field is a finite number\n"
            "within float's range (|value| <= 3.4e38), H >= 1.4012985e-45 and R >= 0. Prints one number per line.\n"
            "I is signed (t1 < t0 gives -I), 0 for a zero direction, and the planet is transparent.\n"
            "Closed forms run in float32, exactly as the shader computes them; 'exact' runs in double.\n"
            "Exit status: 0 success, 1 for a malformed input line or one the method gives no finite value for\n"
            "(one error line naming it, nothing printed), 2 usage error.\n");
        const std::vector<AirmassMethod>& methods = airmassMethods();
        cli::Choices<const AirmassMethod*> choices = {{"list", nullptr}};
        for (const AirmassMethod& m : methods)
            choices.push_back({m.name.c_str(), &m});
        const AirmassMethod* method = findAirmassMethod(kDefaultAirmassMethod);
        cli.addChoice("method", &method, choices, "the method; list: print the names");
        if (!cli.parse(argc, argv)) {
            out << cli.help() << "Methods:\n";
            for (const AirmassMethod& m : methods)
                out << "  " << m.name << ": " << m.description << "\n";
            return;
        }
        if (!method) {
            for (const AirmassMethod& m : methods)
                out << m.name << "\n";
            return;
        }

        // Everything is read and evaluated before anything is printed.
        std::vector<double> airmasses;
        std::string line;
        bool seenContent = false;
        for (long lineNumber = 1; std::getline(in, line); ++lineNumber) {
            const std::string text = trimmed(line);
            if (text.empty())
                continue;
            const std::vector<std::string> fields = fieldsOf(text);
            const bool header = !seenContent && isHeader(fields);
            seenContent = true;
            if (header)
                continue;
            std::string problem;
            const std::optional<AirmassRay> ray = parseRay(fields, problem);
            if (!ray)
                throw std::runtime_error("line " + std::to_string(lineNumber) + ": " + problem);
            const double airmass = evaluateAirmass(*method, *ray, AirmassPrecision::Float32);
            // The published baselines, the fits and march16 overflow for some extreme rays (docs/airmass.md).
            if (!std::isfinite(airmass))
                throw std::runtime_error("line " + std::to_string(lineNumber) + ": " + method->name +
                                         " gives no finite airmass for this ray (" + std::to_string(airmass) +
                                         "); " + kDefaultAirmassMethod + " and exact give one for every accepted line");
            airmasses.push_back(airmass);
        }
        // getline stops at the end or at a read error (standard input a folder, say), which the
        // standard input's stream sees only through stdio's error flag: only the end is accepted.
        if (in.bad() || !in.eof() || (&in == &std::cin && std::ferror(stdin)))
            throw std::runtime_error("cannot read standard input");
        for (const double airmass : airmasses) {
            char number[64];
            std::snprintf(number, sizeof number, "%.12g\n", airmass);
            out << number;
        }
    });
}

} // namespace aurorawall::app
