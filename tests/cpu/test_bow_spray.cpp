// Where a hull under way throws spray from its bow, and how much
// (src/objects/bow_spray.h; the sheet drops' fall in
// src/render/spray_kinematics.h): the published numbers its formulas come
// from, the share's limits, and the bow's waterline found on a box and on
// the built-in boat.
#include "objects/bow_spray.h"
#include "render/spray_kinematics.h"
#include "support/body_fixtures.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>

namespace {

using namespace swell::detail;

// Ochi 1964: slamming when the bow meets the water faster than 12 ft/s,
// for the Mariner's 520 ft (its length between perpendiculars, 528 ft,
// gives the same within 1%); 0.093 sqrt(g L) is that scaled by Froude's law.
TEST(BowSpray, SlamThresholdIsOchis)
{
    constexpr double kFoot_m = 0.3048;
    EXPECT_NEAR(slamThreshold_mps(520.0 * kFoot_m), 12.0 * kFoot_m, 0.02 * 12.0 * kFoot_m);
    // Froude scaling: a quarter the length, half the speed.
    EXPECT_NEAR(slamThreshold_mps(40.0) / slamThreshold_mps(160.0), 0.5, 1e-12);
}

// Gunn and Kinzer 1949, table 2: 2.06 m/s at 0.5 mm, 3.27 m/s at 0.8 mm,
// 4.03 m/s at 1.0 mm.
TEST(BowSpray, SheetDropsFallAtGunnAndKinzersSpeeds)
{
    EXPECT_NEAR(bowSprayFallSpeed_mps(0.5e-3f), 2.06f, 0.03f * 2.06f);
    EXPECT_NEAR(bowSprayFallSpeed_mps(0.8e-3f), 3.27f, 0.03f * 3.27f);
    EXPECT_NEAR(bowSprayFallSpeed_mps(1.0e-3f), 4.03f, 0.01f * 4.03f);
    // Every sheet drop's response time is that speed over g: 0.16 to 0.42 s.
    for (std::uint32_t key = 1; key < 200; ++key)
        for (std::uint32_t drop = SWELL_SPRAY_MIST_DROPS; drop < SWELL_SPRAY_DROPS; ++drop) {
            const float tau_s = bowSprayTau_s(key * 7919u, drop);
            EXPECT_GE(tau_s, bowSprayFallSpeed_mps(0.4e-3f) / 9.81f * 0.999f);
            EXPECT_LE(tau_s, bowSprayFallSpeed_mps(1.0e-3f) / 9.81f * 1.001f);
        }
}

TEST(BowSpray, ShareGrowsWithSpeedAndPlungeAndIsNoneAtRest)
{
    const double length_m = 6.5;
    EXPECT_EQ(bowSprayShare(0.0, length_m, 0.0), 0.0);
    EXPECT_EQ(bowSprayShare(0.0, length_m, 3.0), 0.0) << "a hull at rest throws no bow spray, however it heaves";
    EXPECT_GT(bowSprayShare(1.0, length_m, 0.0), 0.0);
    EXPECT_LT(bowSprayShare(1.0, length_m, 0.0), bowSprayShare(2.0, length_m, 0.0));
    EXPECT_LT(bowSprayShare(4.0, length_m, 0.0), bowSprayShare(4.0, length_m, 0.5));
    EXPECT_LT(bowSprayShare(4.0, length_m, 0.2), bowSprayShare(4.0, length_m, 0.4));
    EXPECT_DOUBLE_EQ(bowSprayShare(10.0, length_m, 10.0), 1.0);
    EXPECT_LE(bowSprayShare(4.0, length_m, 0.0), 0.2 + 1e-12) << "calm water: a fifth at most";
}

// A box of 4 x 1 x 2 m weighing 2050 kg floats 0.25 m deep: its waterline
// at -0.25 m in its own frame, 4 m long, the stem at its forward face's
// corner and the stations on its sides, 1 m out.
TEST(BowSpray, BoxWaterlineAtItsDraft)
{
    const swell::BodyShape shape = swell::test::box({4.0, 1.0, 2.0});
    const std::optional<BowLine> line = bowLineOf(shape, 2050.0, 1025.0, {1.0, 0.0, 0.0}, 0.0);
    ASSERT_TRUE(line);
    EXPECT_NEAR(line->waterline_m, -0.25, 1e-6);
    EXPECT_NEAR(line->length_m, 4.0, 1e-9);
    EXPECT_NEAR(line->stations[0][0].x, 2.0, 1e-9);
    for (int side = 0; side < 2; ++side)
        for (int k = 1; k < SWELL_BOW_SPRAY_STATIONS; ++k) {
            const glm::dvec3 p = line->stations[side][k];
            EXPECT_NEAR(std::abs(p.z), 1.0, 1e-9) << side << " " << k;
            EXPECT_GT(glm::dot(p, line->across) * (side == 0 ? 1.0 : -1.0), 0.0) << "the sides' stations swapped";
            EXPECT_NEAR(p.y, -0.25, 1e-6);
            EXPECT_NEAR(p.x, 2.0 - SWELL_BOW_SPRAY_REACH * 4.0 * k / (SWELL_BOW_SPRAY_STATIONS - 1), 1e-9);
        }
    // Travelling along -z: the stem on the -z face.
    const std::optional<BowLine> beam = bowLineOf(shape, 2050.0, 1025.0, {0.0, 0.0, -3.0}, 0.0);
    ASSERT_TRUE(beam);
    EXPECT_NEAR(beam->length_m, 2.0, 1e-9);
    EXPECT_NEAR(beam->stations[0][0].z, -1.0, 1e-9);
    EXPECT_FALSE(bowLineOf(shape, 2050.0, 1025.0, {0.0, 1.0, 0.0}, 0.0)) << "no heading of travel";
    // Under way at 1.4 m/s the bow wave climbs U^2 / 2g = 0.1 m: the sheet
    // leaves 0.1 m above the waterline; at 10 m/s (5.1 m) it would pass
    // the top, so it is cut half way from the waterline to the top, and the
    // waterline's length stays the waterline's.
    const std::optional<BowLine> slow = bowLineOf(shape, 2050.0, 1025.0, {1.0, 0.0, 0.0}, 1.4);
    ASSERT_TRUE(slow);
    EXPECT_NEAR(slow->climb_m, 1.4 * 1.4 / (2.0 * 9.80665), 1e-9);
    EXPECT_NEAR(slow->stations[0][2].y, -0.25 + slow->climb_m, 1e-6);
    const std::optional<BowLine> fast = bowLineOf(shape, 2050.0, 1025.0, {1.0, 0.0, 0.0}, 10.0);
    ASSERT_TRUE(fast);
    EXPECT_NEAR(fast->climb_m, 0.375, 1e-6);
    EXPECT_NEAR(fast->length_m, 4.0, 1e-9);
}

// The built-in boat at its design displacement floats with its origin on
// the water (docs/BODIES.md): its bow's waterline there, the stem on the
// centreline at its bow (+x), widening aft the same on both sides.
TEST(BowSpray, BuiltinBoatBowAtItsDesignWaterline)
{
    const MeshData hull = makeBuiltinHullVolume("boat");
    swell::BodyShape shape;
    for (const auto& v : hull.vertices)
        shape.positions_m.push_back(glm::dvec3(v.position));
    shape.indices = hull.indices;
    const std::optional<BowLine> line = bowLineOf(shape, 2500.0, 1025.0, {1.0, 0.0, 0.0}, 0.0);
    ASSERT_TRUE(line);
    EXPECT_NEAR(line->waterline_m, 0.0, 0.01);
    EXPECT_GT(line->length_m, 5.0);
    EXPECT_LT(line->length_m, 7.0);
    EXPECT_GT(line->stations[0][0].x, 2.5) << "the stem is at the bow";
    EXPECT_NEAR(line->stations[0][0].z, 0.0, 0.02) << "the stem is on the centreline";
    for (int k = 1; k < SWELL_BOW_SPRAY_STATIONS; ++k) {
        EXPECT_NEAR(line->stations[0][k].z, -line->stations[1][k].z, 0.01) << k;
        EXPECT_GT(std::abs(line->stations[0][k].z), std::abs(line->stations[0][k - 1].z)) << "the bow widens aft";
    }
    // Under way at 5 m/s the sheet leaves 1.27 m up (U^2 / 2g), or half
    // way to the sheer: there the bow has flared out past its waterline.
    const std::optional<BowLine> underWay = bowLineOf(shape, 2500.0, 1025.0, {1.0, 0.0, 0.0}, 5.0);
    ASSERT_TRUE(underWay);
    EXPECT_GT(underWay->climb_m, 0.3);
    EXPECT_LE(underWay->climb_m, 5.0 * 5.0 / (2.0 * 9.80665));
    EXPECT_NEAR(underWay->length_m, line->length_m, 1e-9);
    for (int k = 1; k < SWELL_BOW_SPRAY_STATIONS; ++k)
        EXPECT_GT(std::abs(underWay->stations[0][k].z), std::abs(line->stations[0][k].z)) << "no flare at " << k;
    std::printf("built-in boat: waterline %.3f m, %.2f m long, half-breadth %.2f m %.2f m aft of the stem\n",
                line->waterline_m, line->length_m, std::abs(line->stations[0].back().z),
                line->stations[0][0].x - line->stations[0].back().x);
}

} // namespace
