// What a frame may be asked for (swell/frame_request.h): a still whose
// bodies (and their wake) would be stepped past the history bound is
// refused saying the cost and a history_start_s that fits, which then
// does; a renderer standing close to the time asked steps only the rest;
// and scenes without bodies have no bound.
#include "swell/frame_request.h"

#include "swell/scene/scene.h"
#include "swell/scene/scene_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>

namespace {

swell::Scene boats(int count, bool underWay)
{
    swell::Scene scene = swell::defaultScene();
    scene.objects.clear();
    for (int i = 0; i < count; ++i) {
        swell::SceneObject o;
        o.path = "builtin:boat";
        o.position_m = {30.0 * (i % 16), 0.0, -30.0 * (i / 16)};
        o.floats = true;
        o.mass_kg = 2500.0;
        if (underWay)
            o.velocity_m_per_s = {0.0, 0.0, -4.0};
        scene.objects.push_back(o);
    }
    return scene;
}

TEST(FrameRequest, TwoHundredFiftySixBoatsUnderWayAreRefusedSayingWhatFits)
{
    swell::Scene scene = boats(256, true);
    const std::string problem = swell::historyProblem(scene, 1.0);
    ASSERT_FALSE(problem.empty());
    EXPECT_NE(problem.find("256 floating bodies and their wake of 256 x 256 cells"), std::string::npos) << problem;
    EXPECT_NE(problem.find("over the 30 s"), std::string::npos) << problem;
    std::smatch fits;
    ASSERT_TRUE(std::regex_search(problem, fits, std::regex("history_start_s = (-?[0-9.e+]+) fits"))) << problem;
    scene.historyStart_s = std::stod(fits[1]);
    EXPECT_EQ(swell::historyProblem(scene, 1.0), "");
    EXPECT_LE(swell::historyCost(scene, swell::bodiesStart_s(scene), 1.0).cpu_s, swell::kMaxHistoryCpu_s);
}

TEST(FrameRequest, OneBodyFarInTimeIsRefusedAndAStepFromWhereItStandsIsNot)
{
    const swell::Scene scene = boats(1, false);
    EXPECT_NE(swell::historyProblem(scene, 1e9), "");
    EXPECT_EQ(swell::historyProblem(scene, 10.0), "");
    // A renderer that stands at 1e9 - 10 s steps 10 s more; one after the time asked starts again.
    EXPECT_EQ(swell::historyProblem(scene, 1e9, 1e9 - 10.0), "");
    EXPECT_NE(swell::historyProblem(scene, 1e9, 1e9 + 10.0), "");
    const std::string message = swell::historyProblem(scene, 1e9);
    EXPECT_NE(message.find("1 floating body is stepped from its start at -60 s"), std::string::npos) << message;
}

TEST(FrameRequest, WithoutBodiesNothingIsStepped)
{
    swell::Scene scene = swell::defaultScene();
    EXPECT_EQ(swell::historyProblem(scene, swell::kMaxFrameTime_s), "");
    scene = boats(3, false);
    for (swell::SceneObject& o : scene.objects)
        o.floats = false;
    EXPECT_EQ(swell::historyProblem(scene, swell::kMaxFrameTime_s), "");
}

} // namespace

// A still whose history is estimated at more than a few seconds says so
// before it starts (issue 47: the gale's stills took 21 to 31 s without a
// word); a short one says nothing.
TEST(FrameRequest, ALongHistorySaysWhatItIsSpentOn)
{
    const swell::Scene gale = swell::loadScene(std::filesystem::path(SWELL_SOURCE_DIR) / "scenes" / "gale-under-way.toml");
    const std::string note = swell::historyNote(gale, 20.0);
    EXPECT_NE(note.find("simulating 80 s of 2 floating bodies and their wake of 256 x 256 cells (from their start at "
                        "-60 s) before the frame: about "),
              std::string::npos)
        << note;
    EXPECT_NE(note.find("s of CPU"), std::string::npos) << note;
    swell::Scene released = gale;
    released.historyStart_s = 19.0; // a second of history
    EXPECT_EQ(swell::historyNote(released, 20.0), "");
    EXPECT_EQ(swell::historyNote(swell::Scene{}, 20.0), ""); // no bodies
}
