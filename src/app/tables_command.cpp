#include "app/tables_command.h"

#include "cli/command_line.h"
#include "cli/exit_status.h"
#include "components/tools.h"

#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace aurorawall::app {
namespace {

namespace po = boost::program_options;

// The components' tables: those of options first, then those of a scene (registry order each).
struct Table {
    const components::OptionTable* options = nullptr;
    const components::SceneTable* scene = nullptr;
};

cli::Choices<Table> tables()
{
    cli::Choices<Table> choices;
    for (const components::OptionTable& t : components::componentOptionTables())
        choices.push_back({t.name, {&t, nullptr}});
    for (const components::SceneTable& t : components::componentSceneTables())
        choices.push_back({t.name, {nullptr, &t}});
    return choices;
}

std::string usage()
{
    std::string text;
    const char* head = "Usage: ";
    for (const components::OptionTable& t : components::componentOptionTables()) {
        text += std::string(head) + "aurorawall tables " + t.name + " " + t.usage + "\n";
        head = "       ";
    }
    for (const components::SceneTable& t : components::componentSceneTables()) {
        text += std::string(head) + "aurorawall tables " + std::string(t.name) + " --scene FILE\n";
        head = "       ";
    }
    for (const components::OptionTable& t : components::componentOptionTables())
        text += std::string(t.name) + ": " + t.description;
    for (const components::SceneTable& t : components::componentSceneTables())
        text += std::string(t.name) + ": " + t.description;
    return text + "Exit status: 0 success, 1 output not written or the scene not read, 2 usage error.\n";
}

// "NAME: the scene file whose NAME table to print", with every component's table of a scene.
std::string sceneHelp()
{
    std::string names;
    for (const components::SceneTable& t : components::componentSceneTables())
        names += (names.empty() ? "" : " or ") + std::string(t.name);
    return names + ": the scene file whose " + names + " table to print";
}

// Whether any option of a table of options other than `except` is on the command line.
bool givenOtherOptions(const cli::CommandLine& cli, const components::OptionTable* except)
{
    for (const components::OptionTable& t : components::componentOptionTables())
        if (&t != except)
            for (const std::string& option : t.options)
                if (cli.given(option))
                    return true;
    return false;
}

} // namespace

int runTablesCommand(int argc, char** argv, std::ostream& out, std::ostream& err)
{
    return cli::runCommand("tables", out, err, [&] {
        cli::CommandLine cli("tables", usage());
        std::vector<std::function<void(std::ostream&)>> printers;
        for (const components::OptionTable& t : components::componentOptionTables())
            printers.push_back(t.declare(cli));
        std::string tableName, sceneFile;
        cli.add()("scene", po::value<std::string>(&sceneFile), sceneHelp().c_str());
        cli.addPositional("table", &tableName);
        if (!cli.parse(argc, argv)) {
            out << cli.help();
            return;
        }
        const cli::Choices<Table> choices = tables();
        Table table;
        if (tableName.empty())
            throw cli.usageError("missing the table name (allowed: " + cli::wordsOf(choices) + ")");
        if (!cli::findChoice(choices, tableName, table))
            throw cli.usageError("unknown table '" + common::echoedInput(tableName) + "' (allowed: " + cli::wordsOf(choices) + ")");
        if (table.scene) {
            if (sceneFile.empty() || givenOtherOptions(cli, nullptr))
                throw cli.usageError(std::string(table.scene->name) + " takes --scene FILE and nothing else");
            table.scene->print(sceneFile, out);
            return;
        }
        const components::OptionTable& t = *table.options;
        bool complete = !cli.given("scene") && !givenOtherOptions(cli, &t);
        for (const std::string& option : t.required)
            complete = complete && cli.given(option);
        if (!complete)
            throw cli.usageError(std::string(t.name) + " takes " + t.usage);
        const auto index = static_cast<size_t>(&t - components::componentOptionTables().data());
        printers[index](out);
    });
}

} // namespace aurorawall::app
