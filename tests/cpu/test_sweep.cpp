// Sweeps (swell/dataset/sweep.h): a sample is its (sweep, index) alone, each key's
// value drawn from its own stream (adding a key changes no other), within
// its range (whole numbers reaching both ends), spread evenly over it; a
// one_of picks each choice; the sun's angles set its direction.
#include "swell/dataset/sweep.h"

#include "swell/scene/scene.h"
#include "swell/scene/scene_file.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>

namespace {

namespace fs = std::filesystem;

swell::Sweep sweepFrom(const std::string& name, const std::string& text)
{
    const fs::path path = fs::path(SWELL_TEST_OUTPUT_DIR) / "sweep" / name;
    fs::create_directories(path.parent_path());
    std::ofstream(path) << text;
    return swell::loadSweepFile(path);
}

const std::string kHead = "scene = \"storm\"\ncount = 1000\nseed = 5\n[vary]\n";

TEST(Sweep, ASampleIsItsIndexAloneAndEachKeyItsOwnStream)
{
    const swell::Scene base = swell::defaultScene();
    const swell::Sweep one = sweepFrom("one.toml", kHead + "\"camera.roll_deg\" = [-15.0, 15.0]\n");
    const swell::Sweep two =
        sweepFrom("two.toml", kHead + "\"fog.end_m\" = [900.0, 1200.0]\n\"camera.roll_deg\" = [-15.0, 15.0]\n");
    swell::checkSweep(two, base);
    for (int i : {0, 1, 7, 999}) {
        const swell::SweepSample a = swell::sweepSample(one, base, i), b = swell::sweepSample(two, base, i),
                                 again = swell::sweepSample(one, base, i);
        EXPECT_EQ(a.scene.camera.roll_deg, again.scene.camera.roll_deg);
        EXPECT_EQ(a.scene.camera.roll_deg, b.scene.camera.roll_deg) << "adding fog.end_m moved the roll of sample " << i;
        EXPECT_NE(b.scene.fog.end_m, base.fog.end_m);
    }
    EXPECT_NE(swell::sweepSample(one, base, 0).scene.camera.roll_deg, swell::sweepSample(one, base, 1).scene.camera.roll_deg);
}

TEST(Sweep, ValuesStayInTheirRangesAndSpreadOverThem)
{
    const swell::Scene base = swell::defaultScene();
    const swell::Sweep sweep = sweepFrom("ranges.toml", kHead + "\"camera.roll_deg\" = [-15.0, 15.0]\n"
                                                                "\"waves.wind.seed\" = [3, 6]\n"
                                                                "\"reflection.mode\" = { one_of = [\"fixed\", \"raymarch\"] }\n"
                                                                "\"sun.elevation_deg\" = [10.0, 30.0]\n"
                                                                "\"sun.azimuth_deg\" = 90.0\n");
    swell::checkSweep(sweep, base);
    double sum = 0.0;
    std::set<std::uint32_t> seeds;
    std::set<swell::ReflectionMode> modes;
    for (int i = 0; i < sweep.count; ++i) {
        const swell::Scene s = swell::sweepSample(sweep, base, i).scene;
        ASSERT_GE(s.camera.roll_deg, -15.0);
        ASSERT_LE(s.camera.roll_deg, 15.0);
        sum += s.camera.roll_deg;
        ASSERT_GE(s.sea.wind->seed, 3u);
        ASSERT_LE(s.sea.wind->seed, 6u);
        seeds.insert(s.sea.wind->seed);
        modes.insert(s.reflection.mode);
        const glm::dvec3 sun = glm::normalize(s.sun.direction);
        const double elevation = glm::degrees(std::asin(sun.y));
        ASSERT_GE(elevation, 10.0 - 1e-9);
        ASSERT_LE(elevation, 30.0 + 1e-9);
        ASSERT_NEAR(sun.z, 0.0, 1e-12); // azimuth 90, measured like a heading from -z towards +x: +x (east)
        ASSERT_GT(sun.x, 0.0);
    }
    // The mean of 1000 uniform draws on [-15, 15]: 0 within 4 standard errors (30/sqrt(12)/sqrt(1000) = 0.27).
    EXPECT_NEAR(sum / sweep.count, 0.0, 4 * 0.27);
    EXPECT_EQ(seeds, (std::set<std::uint32_t>{3, 4, 5, 6}));
    EXPECT_EQ(modes.size(), 2u);
}

TEST(Sweep, ARangeOutsideTheParametersOrAListItemThatIsNotThereIsRefusedAtItsPlace)
{
    const swell::Scene base = swell::defaultScene();
    const swell::Sweep tooFast = sweepFrom("fast.toml", kHead + "\"waves.wind.speed_mps\" = [5.0, 80.0]\n");
    try {
        swell::checkSweep(tooFast, base);
        FAIL() << "a wind of 80 m/s was accepted";
    } catch (const swell::InputError& e) {
        EXPECT_EQ(e.place().line, 5);
        EXPECT_NE(e.message().find("outside its range"), std::string::npos) << e.what();
    }
    const swell::Sweep noObject = sweepFrom("object.toml", kHead + "\"objects[9].yaw_deg\" = [0.0, 90.0]\n");
    EXPECT_THROW(swell::checkSweep(noObject, base), swell::InputError);
}

// Issue 48: what a sweep names is refused at its line before anything is
// made: a table's stray key, a scene out of the sweep's folder, an object's
// index the base scene lacks; a sample's varied key keeps its line, and its
// "varied" azimuth is the value drawn, within its range.
swell::InputError sweepRefusal(const std::function<void()>& f)
{
    try {
        f();
    } catch (const swell::InputError& e) {
        return e;
    }
    ADD_FAILURE() << "not refused";
    return swell::InputError({}, "");
}

TEST(Sweep, ATablesUnknownKeyIsNamed)
{
    const swell::InputError e = sweepRefusal([] {
        sweepFrom("weights.toml", kHead + "\"reflection.mode\" = { one_of = [\"fixed\", \"raymarch\"], weights = [1, 2] }\n");
    });
    EXPECT_EQ(e.place().line, 5);
    EXPECT_NE(e.message().find("unknown key 'weights'"), std::string::npos) << e.what();
}

TEST(Sweep, AScenePathOutOfTheSweepsFolderIsRefusedAtItsLine)
{
    for (const char* scene : {"../../../../etc/passwd", "/etc/passwd", "/dev/zero", "", ".", "sub/../.."}) {
        const swell::Sweep sweep =
            sweepFrom("escape.toml", std::string("scene = \"") + scene + "\"\ncount = 1\n");
        const swell::InputError e = sweepRefusal([&] { swell::sweepSceneFile(sweep); });
        EXPECT_EQ(e.place().line, 1) << scene;
        EXPECT_EQ(e.message().find("root:"), std::string::npos) << "the outside file was read: " << e.what();
    }
    // A file beside the sweep, and a name that is not there (a preset's, maybe).
    std::ofstream(fs::path(SWELL_TEST_OUTPUT_DIR) / "sweep" / "beside.toml") << "";
    EXPECT_TRUE(swell::sweepSceneFile(sweepFrom("beside_sweep.toml", "scene = \"beside.toml\"\ncount = 1\n")));
    EXPECT_FALSE(swell::sweepSceneFile(sweepFrom("preset_sweep.toml", "scene = \"storm\"\ncount = 1\n")));
}

TEST(Sweep, AMountedObjectsIndexIsHeldToTheBaseScenesObjects)
{
    swell::Scene base = swell::defaultScene();
    base.objects.resize(2);
    const swell::Sweep sweep = sweepFrom("mount.toml", kHead + "\"camera.mount_object\" = [0, 5]\n");
    const swell::InputError e = sweepRefusal([&] { swell::checkSweep(sweep, base); });
    EXPECT_EQ(e.place().line, 5);
    EXPECT_NE(e.message().find("2 object(s)"), std::string::npos) << e.what();
    swell::checkSweep(sweepFrom("mount_ok.toml", kHead + "\"camera.mount_object\" = [-1, 1]\n"), base);
}

TEST(Sweep, ASamplesVariedKeysPointAtTheirLinesAndKeepTheValuesDrawn)
{
    const swell::Scene base = swell::defaultScene();
    const swell::Sweep sweep = sweepFrom("places.toml", kHead + "\"fog.end_m\" = [900.0, 1200.0]\n"
                                                                "\"sun.azimuth_deg\" = [0.0, 360.0]\n");
    for (int i = 0; i < 200; ++i) {
        const swell::SweepSample sample = swell::sweepSample(sweep, base, i);
        ASSERT_EQ(sample.values.size(), 2u);
        const double azimuth = std::get<double>(sample.values[1]);
        ASSERT_GE(azimuth, 0.0);
        ASSERT_LE(azimuth, 360.0);
        // Measured like a heading: the direction of a camera with that yaw.
        const glm::dvec3 sun = glm::normalize(sample.scene.sun.direction);
        ASSERT_NEAR(std::remainder(glm::degrees(std::atan2(sun.x, -sun.z)) - azimuth, 360.0), 0.0, 1e-9);
        ASSERT_EQ(sample.scene.keyPlaces.at("fog.end_m").line, 5);
        ASSERT_EQ(sample.scene.keyPlaces.at("sun.azimuth_deg").line, 6);
    }
    // A drawn scene refused names the varied key's line in the sweep.
    swell::Scene foggy = base;
    foggy.fog.start_m = 1000.0;
    int index = 0;
    while (swell::sweepSample(sweep, foggy, index).scene.fog.end_m > 1000.0)
        ASSERT_LT(++index, 100);
    const swell::InputError e = sweepRefusal([&] { swell::validateScene(swell::sweepSample(sweep, foggy, index).scene, "base.toml"); });
    EXPECT_EQ(e.place().path, sweep.file.string());
    EXPECT_EQ(e.place().line, 5);
}

} // namespace

namespace {

// A sample may be a clip ([clip]: frames at fps along the simulated time,
// docs/DATASETS.md "Clips"): read as written, its frames' times one frame
// interval apart from the sample's; a clip of 0 frames or 10^9, a rate of
// 0, or a key [clip] does not have refused at its place.
TEST(Sweep, AClipIsReadAndItsBadValuesAreRefusedAtTheirPlace)
{
    const std::string head = "scene = \"storm\"\ncount = 4\n[clip]\n";
    const swell::Sweep sweep = sweepFrom("clip.toml", head + "frames = 12\nfps = 24\n");
    ASSERT_TRUE(sweep.clip);
    EXPECT_EQ(sweep.clip->frames, 12);
    EXPECT_EQ(sweep.clip->fps, 24.0);
    EXPECT_EQ(sweep.clip->frameTime_s(10.0, 6), 10.25);
    EXPECT_FALSE(sweepFrom("still.toml", "scene = \"storm\"\ncount = 4\n").clip) << "a sweep without [clip] is of stills";
    struct Bad {
        std::string body, words;
        int line, column;
    };
    for (const Bad& bad : {Bad{"frames = 0\nfps = 24\n", "clip.frames", 4, 10},
                           Bad{"frames = 1000000000\nfps = 24\n", "clip.frames", 4, 10},
                           Bad{"frames = 8\nfps = 0\n", "clip.fps", 5, 7},
                           Bad{"frames = 8\nfps = 24\nframe_rate = 3\n", "unknown key 'frame_rate' in [clip]", 6, 1},
                           Bad{"fps = 24\n", "clip.frames", 3, 1}}) {
        const swell::InputError e = sweepRefusal([&] { sweepFrom("bad_clip.toml", head + bad.body); });
        EXPECT_EQ(e.place().line, bad.line) << bad.body << e.what();
        EXPECT_EQ(e.place().column, bad.column) << bad.body << e.what();
        EXPECT_NE(e.message().find(bad.words), std::string::npos) << e.what();
    }
}

} // namespace
