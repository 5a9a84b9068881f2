// The scene keys of floating rigid bodies and dry hulls: read, written back,
// and refused with the place and the key when they disagree.
#include "swell/error.h"
#include "swell/scene/scene_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace {

const std::string kBoat = "[[objects]]\n"
                          "path = \"boat.glb\"\n"
                          "hull_node = \"Hull\"\n"
                          "floats = true\n"
                          "density_kg_per_m3 = 300.0\n"
                          "center_of_mass_offset_m = [0.0, -0.2, 0.0]\n"
                          "velocity_m_per_s = [2.0, 0.0, -1.0]\n"
                          "damping_ratio = 0.3\n";

TEST(BodyScene, KeysAreReadAndWrittenBack)
{
    // The model must exist for the scene to load; its content is read only by the renderer.
    const std::filesystem::path folder = std::filesystem::path(SWELL_TEST_OUTPUT_DIR) / "body_scene";
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "boat.glb") << "glTF";
    const swell::Scene scene = swell::parseScene(kBoat, folder / "boat.toml");
    ASSERT_EQ(scene.objects.size(), 1u);
    const swell::SceneObject& o = scene.objects[0];
    EXPECT_EQ(o.hullNode, "Hull");
    EXPECT_TRUE(o.isRigidBody());
    EXPECT_EQ(o.density_kg_per_m3, 300.0);
    EXPECT_EQ(o.centerOfMassOffset_m, glm::dvec3(0.0, -0.2, 0.0));
    EXPECT_EQ(o.velocity_m_per_s, glm::dvec3(2.0, 0.0, -1.0));
    EXPECT_EQ(o.dampingRatio, 0.3);
    const swell::Scene again = swell::parseScene(swell::saveScene(scene), folder / "again.toml");
    EXPECT_EQ(again.objects[0].hullNode, "Hull");
    EXPECT_EQ(again.objects[0].velocity_m_per_s, o.velocity_m_per_s);
    EXPECT_EQ(again.objects[0].density_kg_per_m3, 300.0);
}

// docs/SCENE.md: the body keys "mean nothing" on an object that does not
// float. They are accepted there, kept (a viewer may turn floats on), and
// make no rigid body; even keys that disagree (mass and density both) are
// checked only once the object floats.
TEST(BodyScene, BodyKeysOnAnObjectThatDoesNotFloatAreKeptAndMeanNothing)
{
    const std::string toml = "[[objects]]\npath = \"builtin:buoy\"\nmass_kg = 10.0\ndensity_kg_per_m3 = 500.0\n"
                             "inertia_kg_m2 = [1.0, 0.0, 1.0]\n";
    const swell::Scene scene = swell::parseScene(toml, "not_floating.toml");
    ASSERT_EQ(scene.objects.size(), 1u);
    EXPECT_FALSE(scene.objects[0].isRigidBody());
    EXPECT_EQ(scene.objects[0].mass_kg, 10.0);
    const swell::Scene again = swell::parseScene(swell::saveScene(scene), "again.toml");
    EXPECT_EQ(again.objects[0].density_kg_per_m3, 500.0);
    // Floating, the same keys are refused at their place.
    EXPECT_THROW((void)swell::parseScene(toml + "floats = true\n", "floating.toml"), swell::InputError);
}

struct Refused {
    const char* name;
    std::string toml;
    int line, column;
    std::string message;
};

void PrintTo(const Refused& r, std::ostream* os) { *os << r.name; }

class BodySceneRefused : public testing::TestWithParam<Refused> {};

TEST_P(BodySceneRefused, AtTheKeyWithAReason)
{
    // The place is the offending value's (file:line:column), as for every scene key.
    const Refused& r = GetParam();
    try {
        (void)swell::parseScene(r.toml, "bad.toml");
        FAIL() << "accepted";
    } catch (const swell::InputError& e) {
        EXPECT_EQ(e.place().path, "bad.toml");
        EXPECT_EQ(e.place().line, r.line) << e.what();
        EXPECT_EQ(e.place().column, r.column) << e.what();
        EXPECT_NE(e.message().find(r.message), std::string::npos) << e.what();
    }
}

const std::string kItem = "[[objects]]\npath = \"builtin:buoy\"\n";

INSTANTIATE_TEST_SUITE_P(
    Keys, BodySceneRefused,
    testing::Values(
        Refused{"MassAndDensity", kItem + "floats = true\nmass_kg = 10.0\ndensity_kg_per_m3 = 500.0\n", 5, 21,
                "objects[0] gives both mass_kg"},
        Refused{"OneInertiaMissing", kItem + "floats = true\nmass_kg = 10.0\ninertia_kg_m2 = [1.0, 0.0, 1.0]\n", 5, 17,
                "give all three principal moments"},
        Refused{"ImpossibleInertia", kItem + "floats = true\nmass_kg = 10.0\ninertia_kg_m2 = [1.0, 1.0, 5.0]\n", 5, 17,
                "no solid's"},
        Refused{"HullNodeOfABuiltin", kItem + "hull_node = \"Hull\"\n", 3, 13, "brings its own hull"},
        Refused{"EmptyHullNode", kItem + "hull_node = \"\"\n", 3, 13, "objects[0].hull_node is empty"},
        Refused{"HullNodeNotAString", kItem + "hull_node = 3\n", 3, 13, "must be a string (a glTF node's name)"}),
    [](const testing::TestParamInfo<Refused>& param) { return std::string(param.param.name); });

} // namespace
