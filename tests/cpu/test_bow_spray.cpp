// Where a hull under way throws spray from its bow, and how much
// (src/objects/bow_spray.h; the sheet drops' fall in
// src/render/spray_kinematics.h): the published numbers its formulas come
// from, the share's limits, and the bow's waterline found on a box and on
// the built-in boat.
#include "objects/bow_spray.h"
#include "render/spray_kinematics.h"
#include "support/body_fixtures.h"
#include "swell/gpu/spray.h"

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
        for (std::uint32_t drop = SWELL_SPRAY_MIST_DROPS; drop < SWELL_BOW_SPRAY_DROPS; ++drop) {
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

// Wagner 1932: a wedge of deadrise 30 degrees entering at V wets its
// half-width at (pi / 2) V cot 30 = 2.72 V, its jet twice that, 5.44 V;
// at 10 degrees 8.91 V is the root's speed, but the jet is held at 20
// degrees' (pi cot 20 = 8.63 V); a wall-sided bow throws none.
TEST(BowSpray, SlamJetIsWagners)
{
    EXPECT_NEAR(bowSlamJet_mps(1.0f, 1.0f / std::tan(0.5235988f)), 2.0f * 2.72f, 0.01f);
    EXPECT_NEAR(bowSlamJet_mps(2.0f, 1.0f / std::tan(0.5235988f)), 4.0f * 2.72f, 0.02f);
    EXPECT_NEAR(bowSlamJet_mps(1.0f, 1.0f / std::tan(0.1745329f)), 8.63f, 0.01f);
    EXPECT_EQ(bowSlamJet_mps(3.0f, 0.0f), 0.0f);
    // A plunging bow adds the jet's root to tip speed (0.5 to 1 of it) to
    // the sheet's; a wall-sided one throws the sheet as the hull's speed
    // alone says.
    for (std::uint32_t key = 1; key < 50; ++key) {
        const glm::vec2 forward(1.0f, 0.0f), outward(0.0f, 1.0f);
        const glm::vec3 calm = bowSheetLaunch(key * 7919u, forward, outward, 5.0f, 0.0f, 1.0f);
        const glm::vec3 slam = bowSheetLaunch(key * 7919u, forward, outward, 5.0f, 2.0f, 1.0f);
        const float jet_mps = bowSlamJet_mps(2.0f, 1.0f);
        EXPECT_GE(glm::length(slam - calm), 0.5f * jet_mps * 0.999f);
        EXPECT_LE(glm::length(slam - calm), jet_mps * 1.001f);
        EXPECT_GT(slam.y - calm.y, 0.45f * 0.5f * jet_mps * 0.999f) << "the jet is thrown up";
        EXPECT_EQ(calm, bowSheetLaunch(key * 7919u, forward, outward, 5.0f, 2.0f, 0.0f));
    }
}

// Taylor 1959, Culick 1960: a hole in a sheet opens at sqrt(2 sigma / rho
// h); a soap film of water 1 um thick at about 12 m/s (Culick's 12.0 m/s
// for sigma = 0.072 N/m, fresh water), a 1 mm sea water sheet at 0.377
// m/s, so its holes 0.15 m apart have met (pi r^2 = spacing^2) after
// 0.15 / (0.377 sqrt pi) = 0.22 s.
TEST(BowSpray, SheetTearsAtTheTaylorCulickSpeed)
{
    EXPECT_NEAR(bowSheetRetraction_mps(1e-6f) * std::sqrt((0.072f / 1000.0f) / (0.073f / 1025.0f)), 12.0f, 0.05f);
    EXPECT_NEAR(bowSheetRetraction_mps(1e-3f), 0.377f, 0.002f);
    // Every piece whole at its birth, torn more as it flies, torn through
    // between its thinnest's time and its thickest's.
    const float spacing_m = float(SWELL_BOW_SPRAY_HOLE_SPACING_M);
    const float thinnest_s = spacing_m / (bowSheetRetraction_mps(SWELL_BOW_SPRAY_SHEET_MIN_MM * 1e-3f) * std::sqrt(3.14159265f));
    const float thickest_s = spacing_m / (bowSheetRetraction_mps(SWELL_BOW_SPRAY_SHEET_MAX_MM * 1e-3f) * std::sqrt(3.14159265f));
    EXPECT_NEAR(thinnest_s, 0.16f, 0.005f);
    EXPECT_NEAR(thickest_s, 0.32f, 0.005f);
    for (std::uint32_t key = 1; key < 200; ++key) {
        const std::uint32_t k = key * 2654435761u;
        EXPECT_EQ(bowSheetTorn(k, 0.0f), 0.0f);
        EXPECT_LT(bowSheetTorn(k, 0.1f), bowSheetTorn(k, 0.2f));
        EXPECT_LT(bowSheetTorn(k, 0.99f * thinnest_s), 1.0f);
        EXPECT_EQ(bowSheetTorn(k, 1.01f * thickest_s), 1.0f);
    }
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
    // Wall sided: no flare (a plunging wall throws no Wagner jet); at rest
    // (no climb) none either.
    EXPECT_NEAR(slow->flareCot, 0.0, 1e-9);
    EXPECT_NEAR(fast->flareCot, 0.0, 1e-9);
    EXPECT_EQ(line->flareCot, 0.0);
}

// A wedge-sectioned hull flares out at a known angle: a box whose sides
// lean out 30 degrees from the vertical (cot of the flare to the water:
// tan 30 = 0.577).
TEST(BowSpray, FlareOfALeaningSide)
{
    // A prism 4 m long whose section is a trapezium: 1 m wide at its keel
    // (y = -1), 1 + 2 tan 30 wide at its top (y = 1).
    const double spread = std::tan(0.5235988);
    swell::BodyShape shape = swell::test::box({4.0, 2.0, 1.0});
    for (glm::dvec3& p : shape.positions_m)
        p.z = (p.z > 0.0 ? 1.0 : -1.0) * (0.5 + spread * (p.y + 1.0));
    const std::optional<BowLine> line = bowLineOf(shape, 2050.0, 1025.0, {1.0, 0.0, 0.0}, 3.0);
    ASSERT_TRUE(line);
    EXPECT_NEAR(line->flareCot, spread, 1e-3);
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
    // The boat's bow flares: its sides meet the water at 20 to 70 degrees.
    EXPECT_GT(underWay->flareCot, 1.0 / std::tan(70.0 * 3.14159265 / 180.0));
    EXPECT_LT(underWay->flareCot, 1.0 / std::tan(20.0 * 3.14159265 / 180.0));
    std::printf("built-in boat: flare's cotangent %.3f (%.1f degrees to the water)\n", underWay->flareCot,
                std::atan(1.0 / underWay->flareCot) * 180.0 / 3.14159265);
    std::printf("built-in boat: waterline %.3f m, %.2f m long, half-breadth %.2f m %.2f m aft of the stem\n",
                line->waterline_m, line->length_m, std::abs(line->stations[0].back().z),
                line->stations[0][0].x - line->stations[0].back().x);
}

} // namespace
