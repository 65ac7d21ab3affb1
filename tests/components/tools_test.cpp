// The components' commands (components/tools.h): each compiled-in component's, named once, in
// alphabetical order.
#include "components/tools.h"

#include <gtest/gtest.h>

#include <string>

namespace aurorawall::components {
namespace {

TEST(ComponentTools, CommandsAreNamedOnceInAlphabeticalOrder)
{
    const std::vector<Command>& commands = componentCommands();
    std::string names;
    for (size_t i = 0; i < commands.size(); ++i) {
        names += (i ? " " : "") + std::string(commands[i].name);
        EXPECT_NE(commands[i].run, nullptr) << commands[i].name;
        if (i > 0) {
            EXPECT_LT(std::string(commands[i - 1].name), std::string(commands[i].name));
        }
    }
    EXPECT_EQ(names, "mie plasma");
}

} // namespace
} // namespace aurorawall::components
