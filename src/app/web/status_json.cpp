#include "app/web/status_json.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace aurorawall::app::web {

namespace {

bool isNumber(const std::string& text)
{
    if (text.empty() || !(std::isdigit(static_cast<unsigned char>(text[0])) || text[0] == '-'))
        return false; // also keeps out what strtod takes but JSON does not: inf, nan, .5, 0x1
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    return *end == '\0' && std::isfinite(value);
}

// A JSON string; the protocol's values are printable ASCII, the rest is escaped anyway.
std::string quoted(const std::string& text)
{
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\')
            out += std::string("\\") + c;
        else if (static_cast<unsigned char>(c) < 0x20)
            out += ' ';
        else
            out += c;
    }
    return out + "\"";
}

} // namespace

std::string withMember(const std::string& json, const std::string& name, const std::string& value)
{
    const std::string member = quoted(name) + ":" + quoted(value);
    if (json.size() < 2 || json.back() != '}')
        throw std::invalid_argument("not a JSON object: " + json);
    return json.substr(0, json.size() - 1) + (json == "{}" ? "" : ",") + member + "}";
}

std::string statusJson(const std::string& statusLine)
{
    if (statusLine.rfind("ok ", 0) != 0)
        throw std::invalid_argument("not a status answer: " + statusLine);
    std::istringstream words(statusLine.substr(3));
    std::string word, json;
    while (words >> word) {
        const std::size_t equals = word.find('=');
        std::string member;
        if (equals != std::string::npos) {
            const std::string value = word.substr(equals + 1);
            member = quoted(word.substr(0, equals)) + ":" + (isNumber(value) ? value : quoted(value));
        } else if (word == "paused" || word == "playing") {
            member = std::string("\"paused\":") + (word == "paused" ? "true" : "false");
        } else {
            continue;
        }
        json += (json.empty() ? "{" : ",") + member;
    }
    return json.empty() ? "{}" : json + "}";
}

std::string ranksJson(const cluster::FrameRecord& record, const std::vector<double>& heartbeatAgesS,
                      double heartbeatPeriodS)
{
    const bool watched = heartbeatAgesS.size() >= record.ranks.size();
    std::ostringstream json;
    json.precision(4);
    json << "{\"frame\":" << record.frame << ",\"imbalance\":" << record.imbalance() << ",\"heartbeat_period_s\":";
    if (watched)
        json << heartbeatPeriodS;
    else
        json << "null";
    json << ",\"ranks\":[";
    for (std::size_t r = 0; r < record.ranks.size(); ++r) {
        const cluster::RankReport& report = record.ranks[r];
        json << (r ? "," : "") << "{\"frame\":" << report.frame << ",\"render_ms\":" << report.renderMs
             << ",\"wait_ms\":" << report.waitMs << ",\"heartbeat_age_s\":";
        if (watched)
            json << heartbeatAgesS[r];
        else
            json << "null";
        json << "}";
    }
    json << "]}";
    return json.str();
}

} // namespace aurorawall::app::web
