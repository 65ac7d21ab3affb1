#pragma once
// Runs a command's entry point (run*Command) in the test's process on argv = words, words[0] the
// command's name, with what it prints captured.
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace aurorawall::test {

struct CommandOutput {
    int status;
    std::string out, err;
};

// command(argc, argv, out, err), e.g. runMieCommand, or a lambda that gives airmass its input.
template <class Command>
CommandOutput runInProcess(const Command& command, std::vector<std::string> words)
{
    std::vector<char*> argv;
    for (std::string& w : words)
        argv.push_back(w.data());
    std::ostringstream out, err;
    const int status = command(int(argv.size()), argv.data(), out, err);
    return {status, out.str(), err.str()};
}

// The same on argv = name, options...: runInProcess(runMieCommand, "mie", {"--x", "100"}).
template <class Command>
CommandOutput runInProcess(const Command& command, const std::string& name, std::vector<std::string> options)
{
    options.insert(options.begin(), name);
    return runInProcess(command, std::move(options));
}

// The text's lines, without their newlines.
inline std::vector<std::string> lines(const std::string& text)
{
    std::vector<std::string> result;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        result.push_back(line);
    return result;
}

} // namespace aurorawall::test
