#pragma once
// What components add to the aurorawall binary: their own commands (`aurorawall NAME ...`), their
// tables of error against run time (`aurorawall accuracy --OPTION FILE`, and the sweep of
// `accuracy --scene FILE`), their tables of a scene (`aurorawall tables NAME --scene FILE`) and their
// tables of options (`aurorawall tables NAME --OPTION VALUE ...`). A component with a
// tools/ folder defines `const Tools& NAME::tools::registered()` there; src/components/CMakeLists.txt
// compiles them into aw_component_tools and lists them.
#include "accuracy/scene_view.h"
#include "cli/command_line.h"

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace aurorawall::components {

// One command: argv[0] is its name; it returns the exit status (cli/exit_status.h).
struct Command {
    const char* name;
    const char* summary; // after the name in `aurorawall --help`; further lines indented by 12
    int (*run)(int argc, char** argv, std::ostream& out, std::ostream& err);
};

// A table of `aurorawall accuracy`: `--OPTION FILE` runs it on that scene file with the options
// --wall, --size, --frame and --runs (SceneAccuracySettings); it throws when a file cannot be read
// or is malformed, or when no GL context or shader can be made.
struct AccuracyTable {
    const char* option;
    const char* help;        // the option's line in `accuracy --help`
    const char* description; // its paragraph there, after "--OPTION: "
    void (*run)(const accuracy::SceneAccuracySettings& settings, std::ostream& out);
};

// A table of `aurorawall tables NAME --scene FILE`, printed as CSV from a scene file that lists the
// component; it throws when the file cannot be read, is malformed or does not list the component.
struct SceneTable {
    const char* name;
    const char* description; // its paragraph in `tables --help`, after "NAME: "
    void (*print)(const std::string& sceneFile, std::ostream& out);
};

// A table of `aurorawall tables NAME --OPTION VALUE ...`, computed from its options alone (no scene).
struct OptionTable {
    const char* name;
    const char* usage;       // its options, after "aurorawall tables NAME " and "NAME takes "
    const char* description; // its paragraph in `tables --help`, after "NAME: "
    std::vector<std::string> options;  // the names of the options it declares
    std::vector<std::string> required; // those that must be given
    // Declares its options on the tables command's line; returns what, once the line is parsed,
    // checks their values (throwing cli.usageError) and prints the table as CSV.
    std::function<void(std::ostream& out)> (*declare)(cli::CommandLine& cli);
};

// The sweep of `aurorawall accuracy --scene FILE` (all of SceneAccuracySettings): the quality knobs
// of the march against error and run time, the features' costs or the march's work.
using SceneSweep = void (*)(const accuracy::SceneAccuracySettings& settings, std::ostream& out);

struct Tools {
    std::vector<Command> commands;
    std::vector<AccuracyTable> accuracyTables;
    std::vector<SceneTable> sceneTables;
    SceneSweep sceneSweep = nullptr; // the component whose march it is
    // Whose quality knobs the sweep varies, in `accuracy --help` ("the quality knobs (...):"; lines of
    // at most about 100 characters, the first at most 45).
    const char* sceneSweepKnobs = "";
    std::vector<OptionTable> optionTables = {};
};

// The commands of every compiled-in component, in alphabetical order of their names.
const std::vector<Command>& componentCommands();
// The accuracy tables and scene tables of every compiled-in component, in registry order.
const std::vector<AccuracyTable>& componentAccuracyTables();
const std::vector<SceneTable>& componentSceneTables();
const std::vector<OptionTable>& componentOptionTables();
// The first component's sweep of `accuracy --scene` in registry order, or nullptr.
SceneSweep componentSceneSweep();
// Its sceneSweepKnobs, or "" when there is none.
const char* componentSceneSweepKnobs();

} // namespace aurorawall::components
