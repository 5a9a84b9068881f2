// WaveSampler, the float sampler of the Gerstner sum's height: against the
// exact double evaluation (swell::heightAt) on generated and random sets at
// the fold limit and next to a cusp, single queries against batches of any
// size, on each SIMD path. The Gerstner sum's own math is in test_waves.cpp;
// the wave sets both use are in wave_test_sets.h.
#include "wave_test_sets.h"

#include "support/param_names.h"
#include "swell/scene/spectrum.h"
#include "swell/scene/waves.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace {

using swell::WaveSet;
using namespace swell::test::wave_sets;

using swell::kPi;

// --- WaveSampler --------------------------------------------------------------

TEST(WaveSampler, EmptySamplerIsFlat)
{
    const swell::WaveSampler sampler;
    EXPECT_EQ(sampler.heightAt({1.0, 2.0}), 0.0);
    const swell::WaveSampler fromEmptySet(WaveSet{}, 3.0, {4.0, 5.0});
    EXPECT_EQ(fromEmptySet.heightAt({1.0, 2.0}), 0.0);
    const glm::dvec2 points[2] = {{1.0, 2.0}, {3.0, 4.0}};
    double heights[2] = {-1.0, -1.0};
    fromEmptySet.heightsAt(points, heights);
    EXPECT_EQ(heights[0], 0.0);
    EXPECT_EQ(heights[1], 0.0);
}

TEST(WaveSampler, RejectsInvalidSets)
{
    WaveSet set = handSet();
    set.waves[2].wavelength_m = -1.0;
    try {
        swell::WaveSampler sampler(set, 0.0, {0.0, 0.0});
        FAIL() << "no exception";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "swell::WaveSampler::WaveSampler(): wave 2: wavelength_m must be > 0 (got -1)");
    }
}

class WaveSamplerAgreement : public ::testing::TestWithParam<swell::WaveSampler::Simd> {};

TEST_P(WaveSamplerAgreement, WithinAMillimetreOfTheExactHeight)
{
    // Generated seas from calm to storm, 16 to 64 waves, at the fold limit,
    // with the origin 1e6 m out and t = 1e5 s; points up to 10 km from it.
    const glm::dvec2 origin(1e6, -2e6);
    const double t = 1e5;
    for (int count : {16, 32, 64}) {
        for (double wind : {5.0, 15.0, 35.0}) {
            swell::WindSettings settings;
            settings.windSpeed_mps = wind;
            settings.waveCount = count;
            settings.steepness = 1.0;
            settings.minWavelength_m = 0.2;
            const WaveSet set = swell::generateWaves(settings);
            const swell::WaveSampler sampler(set, t, origin, GetParam());
            EXPECT_EQ(sampler.waveCount(), count);
            const std::vector<glm::dvec2> points = randomPoints(401, 1e4, origin, 12);
            std::vector<double> batch(points.size());
            sampler.heightsAt(points, batch);
            double worst = 0.0;
            double worstBatch = 0.0;
            for (std::size_t i = 0; i < points.size(); ++i) {
                const double exact = swell::heightAt(set, points[i], t);
                worst = std::max(worst, std::abs(sampler.heightAt(points[i]) - exact));
                worstBatch = std::max(worstBatch, std::abs(batch[i] - exact));
            }
            // Requirement 1 mm; float arithmetic gives ~1e-5 m.
            EXPECT_LT(worst, 1e-4) << count << " waves, wind " << wind << " m/s";
            EXPECT_LT(worstBatch, 1e-4) << count << " waves, wind " << wind << " m/s";
        }
    }
}

TEST_P(WaveSamplerAgreement, RandomSetsAtTheFoldLimit)
{
    for (bool aligned : {false, true}) {
        const WaveSet set = randomFoldLimitedSet(40, 21, aligned);
        const swell::WaveSampler sampler(set, 50.0, {0.0, 0.0}, GetParam());
        std::vector<glm::dvec2> world;
        std::vector<double> expected;
        for (glm::dvec2 x0 : randomPoints(500, 300.0, {0.0, 0.0}, 13)) {
            const glm::dvec3 p = displacedPoint(set, x0, 50.0);
            EXPECT_NEAR(sampler.heightAt({p.x, p.z}), p.y, 1e-4);
            world.emplace_back(p.x, p.z);
            expected.push_back(p.y);
        }
        std::vector<double> batch(world.size());
        sampler.heightsAt(world, batch);
        for (std::size_t i = 0; i < world.size(); ++i)
            EXPECT_NEAR(batch[i], expected[i], 1e-4);
    }
}

TEST_P(WaveSamplerAgreement, NextToACusp)
{
    WaveSet set;
    set.waves = {{{1.0, 0.0}, 20.0, 20.0 / (2.0 * kPi), 1.0, 0.0}};
    const swell::WaveSampler sampler(set, 0.0, {0.0, 0.0}, GetParam());
    std::vector<glm::dvec2> world;
    std::vector<double> expected;
    for (int i = -400; i <= 400; ++i) {
        const double x0 = i * 5e-3;
        const glm::dvec3 p = displacedPoint(set, {x0, 0.0}, 0.0);
        EXPECT_NEAR(sampler.heightAt({p.x, p.z}), p.y, 1e-3) << "x0=" << x0;
        world.emplace_back(p.x, p.z);
        expected.push_back(p.y);
    }
    std::vector<double> batch(world.size());
    sampler.heightsAt(world, batch);
    for (std::size_t i = 0; i < world.size(); ++i)
        EXPECT_NEAR(batch[i], expected[i], 1e-3) << "x0=" << (static_cast<double>(i) - 400.0) * 5e-3;
}

TEST_P(WaveSamplerAgreement, BatchOfAnySizeMatchesSingleQueries)
{
    // The batch runs several queries side by side; sizes that do not fill
    // the last vector must come out the same.
    const WaveSet set = handSet(9.0);
    const swell::WaveSampler sampler(set, 2.0, {10.0, 20.0}, GetParam());
    for (std::size_t count : {0u, 1u, 3u, 8u, 13u, 64u}) {
        const std::vector<glm::dvec2> points = randomPoints(static_cast<int>(count), 100.0, {10.0, 20.0}, 14);
        std::vector<double> heights(points.size(), -1.0);
        sampler.heightsAt(points, heights);
        for (std::size_t i = 0; i < points.size(); ++i)
            EXPECT_NEAR(heights[i], sampler.heightAt(points[i]), 2e-5) << "count " << count;
    }
    const std::vector<glm::dvec2> points = randomPoints(5, 100.0, {10.0, 20.0}, 14);
    std::vector<double> tooFew(3);
    EXPECT_THROW(sampler.heightsAt(points, tooFew), std::invalid_argument);
}

INSTANTIATE_TEST_SUITE_P(Simd, WaveSamplerAgreement,
                         ::testing::Values(swell::WaveSampler::Simd::Auto, swell::WaveSampler::Simd::Baseline),
                         [](const auto& param) { return swell::paramName(param.param); });

TEST(WaveSampler, ReportsThePathItUses)
{
    const swell::WaveSampler baseline(handSet(), 0.0, {0.0, 0.0}, swell::WaveSampler::Simd::Baseline);
    EXPECT_EQ(baseline.simd(), swell::WaveSampler::Simd::Baseline);
    const swell::WaveSampler automatic(handSet(), 0.0, {0.0, 0.0});
    EXPECT_NE(automatic.simd(), swell::WaveSampler::Simd::Auto);
}

} // namespace
