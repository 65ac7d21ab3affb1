#include "app/airmass_command.h"

#include "app/cli/command_line.h"
#include "app/cli/exit_status.h"
#include "atmosphere/airmass.h"
#include "common/input_error.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <istream>
#include <optional>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace aurorawall::app {
namespace {

std::string trimmed(const std::string& text)
{
    size_t first = text.find_first_not_of(" \t\r");
    if (first == std::string::npos) return "";
    size_t last = text.find_last_not_of(" \t\r");
    return text.substr(first, last - first + 1);
}

// One CSV line as a ray, or an error message.
std::optional<AirmassRay> parseRay(const std::string& line, std::string& problem)
{
    std::vector<double> values;
    std::stringstream fields(line);
    std::string field;
    while (std::getline(fields, field, ',')) {
        std::string text = trimmed(field);
        char* end = nullptr;
        double value = std::strtod(text.c_str(), &end);
        if (text.empty() || *end != '\0') {
            problem = "field " + std::to_string(values.size() + 1) + " is not a number: '" + echoedInput(text) + "'";
            return std::nullopt;
        }
        if (!std::isfinite(value)) {
            problem = "field " + std::to_string(values.size() + 1) + " is not finite: '" + echoedInput(text) + "'";
            return std::nullopt;
        }
        values.push_back(value);
    }
    if (!line.empty() && line.back() == ',') { // std::getline drops a trailing empty field
        problem = "field " + std::to_string(values.size() + 1) + " is not a number: ''";
        return std::nullopt;
    }
    if (values.size() != 10) {
        problem = "expected 10 comma-separated numbers ox,oy,oz,dx,dy,dz,t0,t1,H,R, got " +
                  std::to_string(values.size()) + " fields";
        return std::nullopt;
    }
    AirmassRay ray{{values[0], values[1], values[2]}, {values[3], values[4], values[5]},
                   values[6], values[7], values[8], values[9]};
    if (!(ray.scaleHeight > 0.0)) {
        problem = "scale height H must be > 0";
        return std::nullopt;
    }
    if (ray.planetRadius < 0.0) {
        problem = "planet radius R must be >= 0";
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
            "a first line starting with a letter is a header; blank lines are skipped). Prints one number per\n"
            "line. I is signed (t1 < t0 gives -I), 0 for a zero direction, and the planet is transparent.\n"
            "Closed forms run in float32, exactly as the shader computes them; 'exact' runs in double.\n"
            "Exit status: 0 success, 1 for a malformed input line (one error line naming it, nothing printed),\n"
            "2 usage error.\n");
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

        std::vector<AirmassRay> rays;
        std::string line;
        bool seenContent = false;
        for (int lineNumber = 1; std::getline(in, line); ++lineNumber) {
            const std::string text = trimmed(line);
            if (text.empty())
                continue;
            const bool header = !seenContent && std::isalpha(static_cast<unsigned char>(text[0]));
            seenContent = true;
            if (header)
                continue;
            std::string problem;
            const std::optional<AirmassRay> ray = parseRay(text, problem);
            if (!ray)
                throw std::runtime_error("line " + std::to_string(lineNumber) + ": " + problem);
            rays.push_back(*ray);
        }
        for (const AirmassRay& ray : rays) {
            char number[64];
            std::snprintf(number, sizeof number, "%.12g\n", evaluateAirmass(*method, ray, AirmassPrecision::Float32));
            out << number;
        }
    });
}

} // namespace aurorawall::app
