// The spectrum's scene keys: waves.wind.spreading and the [waves.swell]
// table read, write back, reach the generated waves, and are refused with a
// place and a reason when they make no sense.
#include "swell/error.h"
#include "swell/scene/scene.h"
#include "swell/scene/scene_file.h"

#include <gtest/gtest.h>

#include <string>

namespace {

using namespace swell;

const char* kPath = "/nowhere/swell.toml"; // parseScene never opens it

// The InputError parseScene throws for `toml`, or a failure.
InputError errorOf(const std::string& toml)
{
    try {
        parseScene(toml, kPath);
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << "no error for:\n" << toml;
    return InputError({}, "");
}

TEST(SpectrumScene, SwellAndSpreadingReadAndWriteBack)
{
    const std::string toml = "[waves.wind]\n"
                             "speed_mps = 9.0\n"
                             "spreading = \"donelan-banner\"\n"
                             "count = 20\n"
                             "[waves.swell]\n"
                             "height_m = 2.5\n"
                             "period_s = 15.0\n"
                             "direction_deg = 45.0\n"
                             "gamma = 8.0\n"
                             "spreading_s = 40.0\n"
                             "count = 10\n";
    const Scene scene = parseScene(toml, kPath);
    ASSERT_TRUE(scene.sea.wind.has_value());
    EXPECT_EQ(scene.sea.wind->spreading, SpreadingModel::DonelanBanner);
    ASSERT_TRUE(scene.sea.wind->swell.has_value());
    const SwellSettings& s = *scene.sea.wind->swell;
    EXPECT_EQ(s.height_m, 2.5);
    EXPECT_EQ(s.period_s, 15.0);
    EXPECT_EQ(s.direction_deg, 45.0);
    EXPECT_EQ(s.gamma, 8.0);
    EXPECT_EQ(s.sMax, 40.0);
    EXPECT_EQ(s.waveCount, 10);
    EXPECT_EQ(resolveWaves(scene).waves.size(), 30u);

    const std::string saved = saveScene(scene);
    EXPECT_NE(saved.find("[waves.swell]"), std::string::npos) << saved;
    EXPECT_NE(saved.find("spreading = \"donelan-banner\""), std::string::npos) << saved;
    const Scene back = parseScene(saved, kPath);
    ASSERT_TRUE(back.sea.wind && back.sea.wind->swell);
    EXPECT_EQ(back.sea.wind->swell->period_s, 15.0);
    EXPECT_EQ(back.sea.wind->swell->sMax, 40.0);
    EXPECT_EQ(saveScene(back), saved);

    // Without a swell, none is written.
    EXPECT_EQ(saveScene(defaultScene()).find("[waves.swell]"), std::string::npos);
}

TEST(SpectrumScene, SwellBeforeWindKeepsBoth)
{
    const Scene scene = parseScene("[waves.swell]\nheight_m = 1.5\n[waves.wind]\nspeed_mps = 6.0\n", kPath);
    ASSERT_TRUE(scene.sea.wind && scene.sea.wind->swell);
    EXPECT_EQ(scene.sea.wind->swell->height_m, 1.5);
    EXPECT_EQ(scene.sea.wind->windSpeed_mps, 6.0);
    // An empty swell table is the default swell.
    const Scene empty = parseScene("[waves]\nwind = {}\nswell = {}\n", kPath);
    ASSERT_TRUE(empty.sea.wind && empty.sea.wind->swell);
    EXPECT_EQ(empty.sea.wind->swell->period_s, SwellSettings{}.period_s);
}

TEST(SpectrumScene, SwellWithoutWindIsRefused)
{
    const InputError e = errorOf("terrain = false\n[waves.swell]\nheight_m = 1.0\n");
    EXPECT_EQ(e.place().line, 2);
    EXPECT_EQ(e.place().column, 1);
    EXPECT_NE(e.message().find("waves.swell adds a swell to the waves generated from waves.wind"), std::string::npos)
        << e.message();
}

TEST(SpectrumScene, TooManyWavesInAllAreRefused)
{
    const InputError e = errorOf("[waves.wind]\ncount = 60\n[waves.swell]\ncount = 8\n");
    EXPECT_EQ(e.place().line, 3);
    EXPECT_NE(e.message().find("waves.wind.count + waves.swell.count = 68; at most 64 waves"), std::string::npos)
        << e.message();
    EXPECT_NO_THROW(parseScene("[waves.wind]\ncount = 56\n[waves.swell]\ncount = 8\n", kPath));
}

TEST(SpectrumScene, BadValuesAreRefused)
{
    EXPECT_NE(errorOf("[waves.wind]\nspreading = \"gaussian\"\n").message().find("waves.wind.spreading"), std::string::npos);
    EXPECT_NE(errorOf("[waves.wind]\n[waves.swell]\nperiod_s = 1.0\n").message().find("waves.swell.period_s = 1 is out of range"),
              std::string::npos);
    EXPECT_NE(errorOf("[waves.wind]\n[waves.swell]\nwavelength_m = 1.0\n").message().find("unknown key"), std::string::npos);
}

} // namespace
