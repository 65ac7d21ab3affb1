#pragma once
// One command's command line over Boost.Program_options: its options, --help, and usage errors that
// name the command and the option ("unrecognised option '--bogus' (see aurorawall tables --help)").
// Every aurorawall command parses through it, so all share one convention (exit_status.h).
//
//   cli::CommandLine cli("tables", "Usage: aurorawall tables deposition --energy-kev E\n...");
//   cli.add()("energy-kev", po::value(&energyKeV)->required(), "electron energy in keV");
//   cli.addChoice("spectrum", &spectrum, kSpectra, "...");
//   if (!cli.parse(argc, argv)) { out << cli.help(); return; }   // --help
//   if (energyKeV <= 0) throw cli.usageError("--energy-kev must be > 0");
#include "cli/choices.h"
#include "common/input_error.h"

#include <boost/program_options.hpp>

#include <memory>
#include <string>

namespace aurorawall::cli {

namespace po = boost::program_options;

class CommandLine {
public:
    // command: the subcommand's name ("tables"; "" for aurorawall itself). usage: the first lines of
    // --help (the usage line and what the command does).
    CommandLine(std::string command, const std::string& usage);

    // Declares options listed in --help; --help (-h) is declared already.
    po::options_description_easy_init add() { return visible_.add_options(); }
    // Declares the positional argument `name` (one word, stored in *value), not listed among the options.
    void addPositional(const char* name, std::string* value);

    // Declares an option whose value is one word of `choices`, stored in *target as the enum; *target's
    // word is the default. The help lists the words ("--backend egl|osmesa|glfw (=egl)"). implicitWord: the value of the bare option
    // (nullptr: the option needs a word).
    template <class E>
    void addChoice(const char* option, E* target, const Choices<E>& choices, const std::string& help,
                   const char* implicitWord = nullptr);

    // Parses argv (argv[0] is the command's name) and stores the values. Returns false if --help was
    // given (nothing else is then checked; print help()). Throws UsageError for an unknown, repeated,
    // malformed or missing option and for a word not among an option's choices.
    bool parse(int argc, char** argv);

    // Whether the option was on the command line (a default does not count).
    bool given(const std::string& option) const;

    std::string help() const;
    // "MESSAGE (see aurorawall COMMAND --help)", to throw.
    common::UsageError usageError(const std::string& message) const;

private:
    std::string command_;
    po::options_description visible_;
    po::options_description hidden_;
    po::positional_options_description positional_;
    po::variables_map values_;
};

template <class E>
void CommandLine::addChoice(const char* option, E* target, const Choices<E>& choices, const std::string& help,
                            const char* implicitWord)
{
    const std::string name = option;
    auto* value = po::value<std::string>()->default_value(wordOf(choices, *target))->notifier(
        [name, target, choices](const std::string& word) {
            if (!findChoice(choices, word, *target))
                throw po::error("--" + name + ": unknown value '" + common::echoedInput(word) + "' (allowed: " + wordsOf(choices) + ")");
        });
    std::string words;
    for (const Choice<E>& c : choices)
        words += (words.empty() ? "" : "|") + std::string(c.word);
    value->value_name(words);
    if (implicitWord)
        value->implicit_value(implicitWord);
    visible_.add_options()(option, value, help.c_str());
}

} // namespace aurorawall::cli
