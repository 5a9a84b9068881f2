// A scene's wake (objects/scene_wake.h) with its bodies: the same scene and
// times give the same poses and the same drawn wake bit for bit, however
// the frames fell, and whether their steps ran ahead on the worker thread;
// the bodies float on the wake; the frame the renderer draws is the surface
// the bodies sample.
#include "objects/scene_bodies.h"
#include "support/body_fixtures.h"
#include "swell/gpu/spray.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <vector>

namespace {

using swell::test::box;
using swell::test::meshOf;
using swell::test::TestWater;

// A 6 m x 2 m x 1.5 m box making 4 m/s along -z, and a 3 m box at rest
// 8 m beside its course, 40 m ahead: the first's wake reaches the second.
swell::Scene twoBoxes()
{
    swell::Scene scene;
    scene.objects = {
        {.path = "boat", .position_m = {0.0, 0.0, 0.0}, .yaw_deg = 90.0, .floats = true, .density_kg_per_m3 = 400.0,
         .velocity_m_per_s = {0.0, 0.0, -4.0}},
        {.path = "buoy", .position_m = {8.0, 0.0, -40.0}, .floats = true, .density_kg_per_m3 = 500.0},
    };
    scene.wake.cells = 128;
    // The bodies start at t = 0, so the tests' times are the wake's own
    // (its steps counted from 0) and the boat starts where it stands.
    scene.historyStart_s = 0.0;
    return scene;
}

struct Meshes {
    swell::detail::MeshData boat = meshOf(box({6.0, 1.5, 2.0}));
    swell::detail::MeshData buoy = meshOf(box({3.0, 1.5, 3.0}));
    std::vector<const swell::detail::MeshData*> list() const { return {&boat, &buoy}; }
};

TEST(WakeBodies, SameSceneAndTimesGiveTheSamePosesAndWakeBitForBit)
{
    const auto waves = std::make_shared<const TestWater>(0.3, 25.0);
    const Meshes meshes;
    const swell::Scene scene = twoBoxes();
    swell::detail::SceneBodies jumped(scene, meshes.list(), waves), framed(scene, meshes.list(), waves);
    ASSERT_NE(jumped.wake(), nullptr);
    // One straight to t, the other through 60 frames a second, and back in
    // time once (a restart from t = 0).
    const double t = 12.34;
    jumped.advanceTo(t);
    for (double s = 0.0; s < 5.0; s += 1.0 / 60.0)
        framed.advanceTo(s);
    framed.advanceTo(1.0);
    for (double s = 1.0; s < t; s += 1.0 / 60.0)
        framed.advanceTo(s);
    framed.advanceTo(t);
    for (std::size_t i = 0; i < 2; ++i)
        EXPECT_EQ(*jumped.poseAt(i, t), *framed.poseAt(i, t)) << "object " << i;
    const swell::detail::WakeFrame a = jumped.wake()->frameAt(t), b = framed.wake()->frameAt(t);
    ASSERT_EQ(a.texels.size(), b.texels.size());
    EXPECT_EQ(a.cornerCell, b.cornerCell);
    EXPECT_EQ(std::memcmp(a.texels.data(), b.texels.data(), a.texels.size() * sizeof(a.texels[0])), 0);
    // ...and the boat did make a wake.
    double largest = 0.0;
    for (const glm::vec4& texel : a.texels)
        largest = std::max(largest, double(std::abs(texel.x)));
    EXPECT_GT(largest, 0.02);
}

// What a frame reads of the bodies at time_s (as the renderer does), and
// the bows' histories, which the spray reads while the next frame's steps
// may already run ahead.
struct FrameRead {
    std::vector<glm::dmat4> poses;
    swell::detail::WakeFrame wake;
    std::vector<std::array<swell::detail::BowSample, SWELL_BOW_SPRAY_HISTORY>> bows;
    std::vector<double> lags_s;
};

FrameRead readFrame(swell::detail::SceneBodies& bodies, double time_s)
{
    FrameRead r;
    for (std::size_t i = 0; i < 2; ++i)
        r.poses.push_back(*bodies.poseAt(i, time_s));
    // The renderer's: the frame the worker made ahead, when it stepped to time_s.
    r.wake = *bodies.sharedWakeFrameAt(time_s);
    EXPECT_EQ(std::memcmp(r.wake.texels.data(), bodies.wakeFrameAt(time_s).texels.data(),
                          r.wake.texels.size() * sizeof(r.wake.texels[0])),
              0);
    return r;
}

void readBows(const swell::detail::SceneBodies& bodies, double time_s, FrameRead& r)
{
    for (std::size_t i = 0; i < 2; ++i) {
        double lag_s = 0.0;
        r.bows.push_back(bodies.bowHistory(i, time_s, lag_s));
        r.lags_s.push_back(lag_s);
    }
}

void expectSameBits(const FrameRead& a, const FrameRead& b, int frame)
{
    for (std::size_t i = 0; i < a.poses.size(); ++i)
        EXPECT_EQ(a.poses[i], b.poses[i]) << "frame " << frame << ", object " << i;
    ASSERT_EQ(a.wake.texels.size(), b.wake.texels.size());
    EXPECT_EQ(a.wake.cornerCell, b.wake.cornerCell) << "frame " << frame;
    EXPECT_EQ(std::memcmp(a.wake.texels.data(), b.wake.texels.data(), a.wake.texels.size() * sizeof(a.wake.texels[0])), 0)
        << "frame " << frame;
    ASSERT_EQ(a.bows.size(), b.bows.size());
    for (std::size_t i = 0; i < a.bows.size(); ++i) {
        EXPECT_EQ(a.lags_s[i], b.lags_s[i]);
        EXPECT_EQ(std::memcmp(a.bows[i].data(), b.bows[i].data(), sizeof(a.bows[i])), 0)
            << "frame " << frame << ", bow " << i;
    }
}

TEST(WakeBodies, StepsTakenAheadOnTheWorkerGiveTheSameFramesBitForBit)
{
    // One set of bodies steps each frame on the calling thread; the other,
    // after each frame, steps towards the next on its worker (as
    // Renderer::anticipate has it) while the frame's bows are read.
    const auto waves = std::make_shared<const TestWater>(0.3, 25.0);
    const Meshes meshes;
    swell::Scene scene = twoBoxes();
    // Steps before t = 0, so the bows have a full history to read.
    scene.historyStart_s = -2.0;
    swell::detail::SceneBodies plain(scene, meshes.list(), waves), ahead(scene, meshes.list(), waves);
    ASSERT_NE(ahead.bow(0), nullptr) << "the boat under way needs a bow for the spray's history";
    const double frame_s = 1.0 / 60.0;
    for (int k = 0; k < 150; ++k) {
        const double t = k * frame_s;
        plain.advanceTo(t);
        ahead.advanceTo(t);
        FrameRead a = readFrame(plain, t), b = readFrame(ahead, t);
        ahead.stepAheadTo(t + frame_s);
        readBows(plain, t, a);
        readBows(ahead, t, b); // waits for the worker, which took the next frame's samples
        expectSameBits(a, b, k);
        if (HasFailure())
            break;
    }
    // The worker stepped to the frame after the last; no step twice, none more.
    plain.advanceTo(150 * frame_s);
    ahead.advanceTo(150 * frame_s);
    EXPECT_EQ(plain.stepsTaken(), ahead.stepsTaken());
    EXPECT_EQ(plain.wakeStepsTaken(), ahead.wakeStepsTaken());
    // The steps ahead were the worker's: its own CPU clock ran.
    EXPECT_GT(ahead.aheadCpu_ms(), 0.0);
    EXPECT_EQ(plain.aheadCpu_ms(), 0.0);
}

TEST(WakeBodies, StepsAheadStayWithinTheirReach)
{
    // Never before the last time asked (the bodies would start again),
    // never more than kMaxStepAhead_s past it (the bows keep no more).
    const auto waves = std::make_shared<const TestWater>(0.3, 25.0);
    const Meshes meshes;
    swell::detail::SceneBodies bodies(twoBoxes(), meshes.list(), waves);
    bodies.stepAheadTo(1.0); // before any advanceTo(): nothing to step from
    EXPECT_EQ(bodies.stepsTaken(), 0);
    bodies.advanceTo(1.0);
    const std::int64_t atOne = bodies.stepsTaken();
    bodies.stepAheadTo(0.5);
    EXPECT_EQ(bodies.stepsTaken(), atOne);
    bodies.stepAheadTo(100.0);
    const std::int64_t lastAhead =
        swell::FloatingBody::lastStepFor(1.0 + swell::detail::SceneBodies::kMaxStepAhead_s);
    EXPECT_EQ(bodies.stepsTaken(), 2 * lastAhead); // two bodies, from step 0
    // ...and the frame there is the one stepped to directly.
    swell::detail::SceneBodies direct(twoBoxes(), meshes.list(), waves);
    const double t = 1.0 + swell::detail::SceneBodies::kMaxStepAhead_s;
    bodies.advanceTo(t);
    direct.advanceTo(t);
    expectSameBits(readFrame(bodies, t), readFrame(direct, t), 0);
}

TEST(WakeBodies, ABodyAtRestRidesThePassingWake)
{
    // On flat water the buoy lies still; the boat's wake, passing it, moves
    // it. With the wake off it does not move at all.
    const auto flat = std::make_shared<const TestWater>();
    const Meshes meshes;
    swell::Scene scene = twoBoxes();
    swell::detail::SceneBodies with(scene, meshes.list(), flat);
    scene.wake.enabled = false;
    swell::detail::SceneBodies without(scene, meshes.list(), flat);
    EXPECT_EQ(without.wake(), nullptr);
    double withRange = 0.0, withoutRange = 0.0;
    with.advanceTo(0.0);
    without.advanceTo(0.0);
    const double rest_m = (*with.poseAt(1, 0.0))[3].y;
    for (double t = 0.0; t < 25.0; t += 0.1) {
        with.advanceTo(t);
        without.advanceTo(t);
        withRange = std::max(withRange, std::abs((*with.poseAt(1, t))[3].y - rest_m));
        withoutRange = std::max(withoutRange, std::abs((*without.poseAt(1, t))[3].y - rest_m));
    }
    EXPECT_GT(withRange, 0.01);
    EXPECT_LT(withoutRange, 1e-9);
}

TEST(WakeBodies, TheDrawnFrameIsTheWaterBodiesSample)
{
    // At a wake step's time the frame holds that step's heights exactly, so
    // what is drawn there is what the bodies floated on.
    const auto flat = std::make_shared<const TestWater>();
    const Meshes meshes;
    swell::detail::SceneBodies bodies(twoBoxes(), meshes.list(), flat);
    const double t = 200.0 / swell::detail::kWakeStepsPerSecond;
    bodies.advanceTo(t);
    const swell::detail::SceneWake& wake = *bodies.wake();
    const swell::detail::WakeFrame frame = wake.frameAt(t);
    int nonZero = 0;
    for (double z = -60.0; z <= 10.0; z += 0.7)
        for (double x = -15.0; x <= 15.0; x += 0.9) {
            const double h = wake.heightAt({x, z}, t);
            EXPECT_EQ(frame.heightAt({x, z}), h) << x << ", " << z;
            EXPECT_EQ(bodies.surface().heightAt({x, z}, t), h) << x << ", " << z;
            nonZero += std::abs(h) > 1e-3;
        }
    EXPECT_GT(nonZero, 100);
}

} // namespace
