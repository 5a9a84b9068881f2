// The [seabed] of scene files (docs/SCENE.md): read into Scene::seabed,
// written back by saveScene() (a round trip), refused at the key's file,
// line and column when wrong, and what a change to it costs a running
// renderer (ParameterEffect::Seabed and nothing else).
#include "support/expect_input_error.h"
#include "swell/scene/parameters.h"
#include "swell/scene/scene.h"
#include "swell/scene/scene_changes.h"
#include "swell/scene/scene_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;
using namespace swell;

namespace {

fs::path folder()
{
    const fs::path f = fs::path(SWELL_TEST_OUTPUT_DIR) / "seabed_scene";
    fs::create_directories(f);
    std::ofstream(f / "floor.png", std::ios::binary) << "png"; // read as an image only when drawn
    return f;
}

std::string scenePath() { return (folder() / "coast.toml").string(); }

const char* kCoast = R"(terrain = false

[seabed]
toe_depth_m = 40.0

[[seabed.beaches]]
shore_point_m = [100.0, -250.0]
seaward_azimuth_deg = 200.0
slope = 0.02
length_m = 800.0
top_m = 4.0
land_width_m = 30.0

[[seabed.shelves]]
edge_point_m = [0.0, 300.0]
seaward_azimuth_deg = 200.0
depth_m = 8.0
slope = 0.1
width_m = 200.0
length_m = 600.0

[[seabed.breakwaters]]
start_m = [-50.0, 0.0]
end_m = [50.0, 20.0]
crest_m = 4.5
crest_width_m = 8.0
side_slope = 0.5

[seabed.heightmap]
path = "floor.png"
center_m = [500.0, 500.0]
size_m = [256.0, 128.0]
black_height_m = -30.0
white_height_m = 12.0
)";

} // namespace

TEST(SeabedSceneFile, ReadsEveryKey)
{
    const Scene scene = parseScene(kCoast, scenePath());
    const SeabedSettings& s = scene.seabed;
    EXPECT_EQ(s.toeDepth_m, 40.0);
    ASSERT_EQ(s.beaches.size(), 1u);
    EXPECT_EQ(s.beaches[0].shorePoint_m, glm::dvec2(100.0, -250.0));
    EXPECT_EQ(s.beaches[0].seawardAzimuth_deg, 200.0);
    EXPECT_EQ(s.beaches[0].slope, 0.02);
    EXPECT_EQ(s.beaches[0].length_m, 800.0);
    EXPECT_EQ(s.beaches[0].top_m, 4.0);
    EXPECT_EQ(s.beaches[0].landWidth_m, 30.0);
    ASSERT_EQ(s.shelves.size(), 1u);
    EXPECT_EQ(s.shelves[0].edgePoint_m, glm::dvec2(0.0, 300.0));
    EXPECT_EQ(s.shelves[0].depth_m, 8.0);
    EXPECT_EQ(s.shelves[0].slope, 0.1);
    EXPECT_EQ(s.shelves[0].width_m, 200.0);
    EXPECT_EQ(s.shelves[0].length_m, 600.0);
    ASSERT_EQ(s.breakwaters.size(), 1u);
    EXPECT_EQ(s.breakwaters[0].start_m, glm::dvec2(-50.0, 0.0));
    EXPECT_EQ(s.breakwaters[0].end_m, glm::dvec2(50.0, 20.0));
    EXPECT_EQ(s.breakwaters[0].crest_m, 4.5);
    EXPECT_EQ(s.breakwaters[0].crestWidth_m, 8.0);
    EXPECT_EQ(s.breakwaters[0].sideSlope, 0.5);
    EXPECT_EQ(s.heightmap.path, "floor.png");
    EXPECT_EQ(s.heightmap.center_m, glm::dvec2(500.0, 500.0));
    EXPECT_EQ(s.heightmap.size_m, glm::dvec2(256.0, 128.0));
    EXPECT_EQ(s.heightmap.blackHeight_m, -30.0);
    EXPECT_EQ(s.heightmap.whiteHeight_m, 12.0);
}

TEST(SeabedSceneFile, RoundTrips)
{
    const Scene scene = parseScene(kCoast, scenePath());
    const std::string saved = saveScene(scene);
    const Scene again = parseScene(saved, scenePath());
    EXPECT_EQ(saveScene(again), saved);
    for (const Parameter& p : parameters()) {
        if (!p.key.starts_with("seabed."))
            continue;
        for (std::size_t i = 0; i < listSize(scene, p.list); ++i) {
            EXPECT_EQ(formatValue(p, p.get(again, i)), formatValue(p, p.get(scene, i))) << p.key << "[" << i << "]";
        }
    }
    EXPECT_EQ(again.seabed.heightmap.path, "floor.png");
    // A scene without a seabed writes none.
    EXPECT_EQ(saveScene(Scene{}).find("seabed"), std::string::npos);
}

TEST(SeabedSceneFile, RefusesBadSeabedsAtTheirPlace)
{
    struct Bad {
        std::string toml;
        int line, column;
        std::string message;
    };
    const Bad cases[] = {
        {"[[seabed.beaches]]\nslope = 0.0\n", 2, 9, "seabed.beaches[0].slope = 0 is out of range"},
        {"[[seabed.beaches]]\nslope = -0.02\n", 2, 9, "seabed.beaches[0].slope"},
        {"[[seabed.shelves]]\nslope = 0.1\n\n[[seabed.shelves]]\nslope = 0\n", 5, 9, "seabed.shelves[1].slope"},
        {"[[seabed.breakwaters]]\nstart_m = [5.0, 5.0]\nend_m = [5.0, 5.0]\n", 3, 9, "seabed.breakwaters[0] has no length"},
        {"[seabed.heightmap]\npath = \"missing.png\"\n", 2, 8, "seabed.heightmap.path: file"},
        {"[seabed.heightmap]\npath = \"\"\n", 2, 8, "seabed.heightmap.path is empty"},
        {"[seabed.heightmap]\npath = \"floor.png\"\nblack_height_m = nan\n", 3, 18, "seabed.heightmap.black_height_m"},
        {"[seabed.heightmap]\npath = \"floor.png\"\nwhite_height_m = inf\n", 3, 18, "seabed.heightmap.white_height_m"},
        {"[seabed.heightmap]\ncenter_m = [1.0, 2.0]\n", 2, 12, "seabed.heightmap needs a path"},
        {"[seabed.heightmap]\npath = \"floor.png\"\nsize_m = [0.0, 10.0]\n", 3, 11, "seabed.heightmap.size_m[0]"},
        {"[seabed]\ntoe_depth_m = 0.0\n", 2, 15, "seabed.toe_depth_m"},
        {"[[seabed.beaches]]\nslop = 0.1\n", 2, 1, "did you mean 'seabed.beaches[0].slope'"},
    };
    for (const Bad& bad : cases) {
        SCOPED_TRACE(bad.toml);
        const InputError e = test::expectInputError([&] { parseScene(bad.toml, scenePath()); });
        EXPECT_EQ(e.place().path, scenePath());
        EXPECT_EQ(e.place().line, bad.line);
        EXPECT_EQ(e.place().column, bad.column);
        EXPECT_NE(e.message().find(bad.message), std::string::npos) << e.message();
    }
}

// A seabed standing above the camera (the camera on land) is allowed.
TEST(SeabedSceneFile, AllowsASeabedAboveTheCamera)
{
    EXPECT_NO_THROW(parseScene("[camera]\nposition_m = [0.0, 2.0, 0.0]\n\n[[seabed.beaches]]\nshore_point_m = [0.0, 500.0]\n"
                               "seaward_azimuth_deg = 180.0\ntop_m = 20.0\n",
                               scenePath()));
}

// A change to the seabed rebuilds the seabed and nothing else; adding a
// shape or naming another heightmap too.
TEST(SeabedSceneFile, ChangesRebuildTheSeabedAlone)
{
    const Scene before = parseScene(kCoast, scenePath());
    Scene after = before;
    after.seabed.beaches[0].slope = 0.03;
    EXPECT_EQ(sceneChanges(before, after), ParameterEffect::Seabed);
    after = before;
    after.seabed.breakwaters.push_back(after.seabed.breakwaters[0]);
    EXPECT_EQ(sceneChanges(before, after), ParameterEffect::Seabed);
    after = before;
    after.seabed.heightmap.path = "other.png";
    EXPECT_EQ(sceneChanges(before, after), ParameterEffect::Seabed);
    after = before;
    after.seabed.toeDepth_m = 60.0;
    EXPECT_EQ(sceneChanges(before, after), ParameterEffect::Seabed);
    EXPECT_EQ(sceneChanges(before, before), ParameterEffect::Frame);
}
