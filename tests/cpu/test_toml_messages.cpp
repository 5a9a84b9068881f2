// Messages for two mistakes that TOML makes easy, pointing where the fix goes:
// a top-level key written after a [table] (TOML puts it in that table), and
// an array whose closing ']' is missing (the parser only notices on the next
// line, which it reads as more of the array).
#include "swell/error.h"
#include "swell/scene/scene_file.h"

#include <gtest/gtest.h>

#include <string>

namespace {

swell::InputError tomlError(const std::string& toml)
{
    try {
        swell::parseScene(toml, "mistake.toml");
    } catch (const swell::InputError& e) {
        return e;
    }
    ADD_FAILURE() << "no error for:\n" << toml;
    return swell::InputError({}, "");
}

TEST(TomlMessages, TopLevelKeyAfterATableSaysTopLevelKeysComeFirst)
{
    const swell::InputError e = tomlError("terrain = true\n[camera]\nposition_m = [0.0, 6.0, 0.0]\ndebug_view = \"normals\"\n");
    EXPECT_EQ(e.place().line, 4);
    EXPECT_NE(e.message().find("unknown key 'camera.debug_view'"), std::string::npos) << e.message();
    EXPECT_NE(e.message().find("'debug_view' is a top-level key"), std::string::npos) << e.message();
    EXPECT_NE(e.message().find("above the first [table]"), std::string::npos) << e.message();
}

TEST(TomlMessages, AnUnknownKeyInATableDoesNotClaimToBeTopLevel)
{
    const swell::InputError e = tomlError("[camera]\nheight_m = 3.0\n");
    EXPECT_EQ(e.message().find("top-level"), std::string::npos) << e.message();
}

TEST(TomlMessages, MissingClosingBracketIsReportedOnTheArraysLine)
{
    //                                  column 28: just after "0.0"
    const swell::InputError e = tomlError("[camera]\nposition_m = [0.0, 6.0, 0.0\npitch_deg = -5.0\n");
    EXPECT_EQ(e.place().line, 2) << e.what();
    EXPECT_EQ(e.place().column, 28) << e.what();
    EXPECT_NE(e.message().find("no closing ']'"), std::string::npos) << e.message();
}

TEST(TomlMessages, MissingBracketBeforeATableHeaderIsReportedOnTheArraysLine)
{
    const swell::InputError e = tomlError("[sun]\ncolor = [1.0, 0.9, 0.8   # warm\n\n[fog]\nstart_m = 10.0\n");
    EXPECT_EQ(e.place().line, 2) << e.what();
    EXPECT_EQ(e.place().column, 23) << e.what();
}

TEST(TomlMessages, MissingCommaInAOneElementALineArrayStaysWhereTheParserStopped)
{
    // The '[' ends its line: the fault is the missing comma after 6.0, not a bracket.
    const swell::InputError e = tomlError("[camera]\nposition_m = [\n  0.0,\n  6.0\n  0.0\n]\n");
    EXPECT_EQ(e.place().line, 5) << e.what();
    EXPECT_EQ(e.message().find("no closing"), std::string::npos) << e.message();
}

// A string whose closing quote is missing runs into the line's end, which
// the parser calls an unescaped control character: say that the quote is
// missing, at the opening quote.
TEST(TomlMessages, AStringWithoutItsClosingQuoteIsReportedAtItsOpeningQuote)
{
    const swell::InputError e = tomlError("[[objects]]\npath = \"builtin:boat\nfloats = true\n");
    EXPECT_EQ(e.place().line, 2) << e.what();
    EXPECT_EQ(e.place().column, 8) << e.what();
    EXPECT_NE(e.message().find("no closing \" before the end of its line"), std::string::npos) << e.message();
    EXPECT_EQ(e.message().find("control character"), std::string::npos) << e.message();

    // A closed string and a quote in a comment before it do not count.
    const swell::InputError literal = tomlError("[[objects]]\npath = 'a' # \"\nhull_node = 'Hull\n");
    EXPECT_EQ(literal.place().line, 3) << literal.what();
    EXPECT_EQ(literal.place().column, 13) << literal.what();
    EXPECT_NE(literal.message().find("no closing '"), std::string::npos) << literal.message();
}

// The right name in another unit is suggested, with the unit the key takes,
// though it is further than a typo from what was written.
TEST(TomlMessages, AKeyInAnotherUnitSuggestsTheKeyAndItsUnit)
{
    const swell::InputError e = tomlError("[waves.wind]\ndirection_rad = 1.2\n");
    EXPECT_NE(e.message().find("did you mean 'waves.wind.direction_deg', in deg?"), std::string::npos) << e.message();
    const swell::InputError inItem = tomlError("[[camera.path]]\nyaw_rad = 1.2\n");
    EXPECT_NE(inItem.message().find("did you mean 'camera.path[0].yaw_deg', in deg?"), std::string::npos)
        << inItem.message();
}

} // namespace
