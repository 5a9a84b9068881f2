// Sweeps (swell/sweep.h): a sample is its (sweep, index) alone, each key's
// value drawn from its own stream (adding a key changes no other), within
// its range (whole numbers reaching both ends), spread evenly over it; a
// one_of picks each choice; the sun's angles set its direction.
#include "swell/sweep.h"

#include "swell/scene.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
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
        ASSERT_GE(s.waves.wind->seed, 3u);
        ASSERT_LE(s.waves.wind->seed, 6u);
        seeds.insert(s.waves.wind->seed);
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

} // namespace
