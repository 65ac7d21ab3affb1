#pragma once
// What components add to the aurorawall binary: their own commands (`aurorawall NAME ...`), their
// tables of error against run time (`aurorawall accuracy --OPTION FILE`, and the sweep of
// `accuracy --scene FILE`), their tables of a scene (`aurorawall tables NAME --scene FILE`) and their
// tables of options (`aurorawall tables NAME --OPTION VALUE ...`), and its quality knobs that the sweep
// of `accuracy --scene` varies besides those of the march's component. A component with a
// tools/ folder defines `const Tools& NAME::tools::registered()` there; src/components/CMakeLists.txt
// compiles them into aw_component_tools and lists them.
#include "accuracy/scene_view.h"
#include "cli/command_line.h"
#include "scene/scene.h"

#include <functional>
#include <iosfwd>
#include <string>
#include <utility>
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

// A quality knob of a listed component that the sweep of `accuracy --scene` varies alone, every other
// knob at the scene's value.
struct SweepKnob {
    std::string name; // its rows' knob in the table
    // Its values, coarse to fine: each one's label in the table and what sets it in a scene.
    std::vector<std::pair<std::string, std::function<void(scene::Scene&)>>> values;
    std::function<void(scene::Scene&)> setFinest; // the value of its references
    std::string finest;                           // that value in words ("16 steps per cell")
    // What its finest value refines. The model itself (the cells of a simulation whose frames the CPU
    // reference samples too): its rows compare with both references made again at its finest. Or only
    // the GPU's approximation of it (a march's steps, which the CPU reference integrates exactly): it is
    // part of every row's GPU reference, and its own rows compare with the scene's defaults at its finest.
    bool refinesModel = false;
    std::string gpuReference; // what the table's head adds to the GPU reference (", ..."); empty: nothing
    std::string cpuReference; // and to the CPU reference
};

// A component's sweep knobs on a scene: none when the scene does not list it (or its knobs do not apply).
using SweepKnobs = std::vector<SweepKnob> (*)(const scene::Scene& scene);

struct Tools {
    std::vector<Command> commands;
    std::vector<AccuracyTable> accuracyTables;
    std::vector<SceneTable> sceneTables;
    SceneSweep sceneSweep = nullptr; // the component whose march it is
    // Whose quality knobs the sweep varies, in `accuracy --help` ("the quality knobs (...):"; lines of
    // at most about 100 characters, the first at most 45).
    const char* sceneSweepKnobs = "";
    std::vector<OptionTable> optionTables = {};
    SweepKnobs sweepKnobs = nullptr;
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
// The sweep knobs of every compiled-in component on `scene`, in registry order.
std::vector<SweepKnob> componentSweepKnobs(const scene::Scene& scene);

} // namespace aurorawall::components
