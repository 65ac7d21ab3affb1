#include "cli/exit_status.h"

#include "common/input_error.h"

#include <ostream>
#include <stdexcept>

namespace aurorawall::cli {

int exitStatusOf(const std::exception& error)
{
    return dynamic_cast<const common::UsageError*>(&error) ? kUsageError : kRuntimeFailure;
}

std::string errorLine(const std::string& command, const std::string& message)
{
    return "aurorawall" + (command.empty() ? "" : " " + command) + ": " + message;
}

int runCommand(const std::string& command, std::ostream& out, std::ostream& err, const std::function<void()>& body)
{
    try {
        body();
        out.flush();
        if (!out)
            throw std::runtime_error("cannot write the output");
    } catch (const std::exception& e) {
        err << errorLine(command, e.what()) << std::endl;
        return exitStatusOf(e);
    }
    return kSuccess;
}

} // namespace aurorawall::cli
