#include "cli/command_line.h"

#include <sstream>

namespace aurorawall::cli {
namespace {

// Boost.Program_options' messages quote what was typed (an option, its value) from substitutions that
// its error class keeps protected; a class derived from it may reach them, to pass each through
// echoedInput.
struct EchoedErrorValues : po::error_with_option_name {
    static void cut(po::error_with_option_name& error)
    {
        for (auto& [placeholder, text] : error.*(&EchoedErrorValues::m_substitutions))
            text = common::echoedInput(text);
    }
};

} // namespace

CommandLine::CommandLine(std::string command, const std::string& usage)
    : command_(std::move(command)), visible_(usage + "\nOptions")
{
    visible_.add_options()("help,h", "show this help and exit");
}

void CommandLine::addPositional(const char* name, std::string* value)
{
    hidden_.add_options()(name, po::value(value));
    positional_.add(name, 1);
}

bool CommandLine::parse(int argc, char** argv)
{
    po::options_description all;
    all.add(visible_).add(hidden_);
    try {
        po::store(po::command_line_parser(argc, argv).options(all).positional(positional_).run(), values_);
        if (values_.count("help"))
            return false;
        po::notify(values_);
    } catch (po::error_with_option_name& e) {
        EchoedErrorValues::cut(e);
        throw usageError(e.what());
    } catch (const po::too_many_positional_options_error&) {
        // Name the first argument past those the command takes (its words without options).
        const std::vector<std::string> words = po::collect_unrecognized(
            po::command_line_parser(argc, argv).options(all).allow_unregistered().run().options, po::include_positional);
        const unsigned taken = positional_.max_total_count();
        throw usageError(words.size() > taken ? "unexpected argument '" + common::echoedInput(words[taken]) + "'"
                                              : std::string("too many arguments"));
    } catch (const po::error& e) {
        throw usageError(e.what());
    }
    return true;
}

bool CommandLine::given(const std::string& option) const
{
    const auto found = values_.find(option);
    return found != values_.end() && !found->second.defaulted();
}

std::string CommandLine::help() const
{
    std::ostringstream text;
    text << visible_;
    return text.str();
}

common::UsageError CommandLine::usageError(const std::string& message) const
{
    return common::UsageError(message + " (see aurorawall" + (command_.empty() ? "" : " " + command_) + " --help)");
}

} // namespace aurorawall::cli
