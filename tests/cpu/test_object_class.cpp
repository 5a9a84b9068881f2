// An object's class key (docs/SCENE.md, [[objects]] `class`; issue 46, item
// 4): read, written back and taken by the labels as the object's class;
// an empty one, one that is not a string, or the name of a class the labels
// give to what is not an object, refused at the key's file:line:column.
#include "support/expect_input_error.h"
#include "swell/dataset/labels.h"
#include "swell/error.h"
#include "swell/scene/scene_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace {

const std::string kTwoBuoys = "[[objects]]\npath = \"builtin:buoy\"\nclass = \"cardinal_mark_north\"\n"
                              "[[objects]]\npath = \"builtin:buoy\"\n";

TEST(ObjectClass, TheKeyIsTheObjectsClassInTheLabels)
{
    const swell::Scene scene = swell::parseScene(kTwoBuoys, "classes.toml");
    ASSERT_EQ(scene.objects.size(), 2u);
    EXPECT_EQ(scene.objects[0].className, "cardinal_mark_north");
    EXPECT_EQ(swell::objectClassOf(scene.objects[0]), "cardinal_mark_north");
    EXPECT_EQ(swell::objectClassOf(scene.objects[1]), "buoy"); // no key: the model's name
    const std::vector<std::string> classes = swell::labelClassesOf(scene);
    ASSERT_EQ(classes.size(), std::size_t(SWELL_LABEL_FIRST_OBJECT_CLASS) + 2);
    EXPECT_EQ(classes[SWELL_LABEL_FIRST_OBJECT_CLASS], "cardinal_mark_north");
    EXPECT_EQ(classes[SWELL_LABEL_FIRST_OBJECT_CLASS + 1], "buoy");
    const swell::Scene again = swell::parseScene(swell::saveScene(scene), "again.toml");
    EXPECT_EQ(again.objects[0].className, "cardinal_mark_north");
    EXPECT_EQ(again.objects[1].className, "");
}

// Each refusal at the offending value's file:line:column, with its reason.
TEST(ObjectClass, AnEmptyOrFixedClassIsRefusedAtItsPlace)
{
    const std::string item = "[[objects]]\npath = \"builtin:buoy\"\n";
    const struct {
        std::string toml;
        int line;
        const char* message;
    } cases[] = {
        {item + "class = \"\"\n", 3, "objects[0].class is empty"},
        {item + "class = 3\n", 3, "must be a string"},
        {item + "class = \"a\\u0007b\"\n", 3, "control character"},
        {item + "class = \"water\"\n", 3, "objects[0].class = \"water\" is the name of a class the labels give"},
        {item + item + "class = \"\"\n", 5, "objects[1].class is empty"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.toml);
        const swell::InputError e = swell::test::expectInputError([&] { (void)swell::parseScene(c.toml, "bad.toml"); });
        EXPECT_EQ(e.place().path, "bad.toml");
        EXPECT_EQ(e.place().line, c.line) << e.what();
        EXPECT_EQ(e.place().column, 9) << e.what();
        EXPECT_NE(e.message().find(c.message), std::string::npos) << e.what();
    }
}

} // namespace
