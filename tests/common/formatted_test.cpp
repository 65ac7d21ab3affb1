// common::formatted: printf-style text of any length, nothing cut.
#include "common/formatted.h"

#include <gtest/gtest.h>

#include <string>

using aurorawall::common::formatted;

TEST(Formatted, KeepsTextOfAnyLength)
{
    const std::string path(5000, 'p');
    const std::string text = formatted("table %d: %s: %.0f ms", 7, path.c_str(), 12.4);
    EXPECT_EQ(text, "table 7: " + path + ": 12 ms");
    EXPECT_EQ(formatted("%.8g,%.8g", 3.0805413e8, -1.5e-300), "3.0805413e+08,-1.5e-300");
    EXPECT_EQ(formatted("%s", ""), "");
}
