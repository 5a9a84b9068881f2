// Gerstner waves on the CPU: the wave function against hand-written sums and
// finite differences, the inverse (heightAt) against round trips, phase
// precision far from the origin, the fold limit and validation. WaveSampler
// against the exact double evaluation is in test_wave_sampler.cpp; the wave
// sets both use are in wave_test_sets.h.
#include "wave_test_sets.h"

#include "swell/gpu/limits.h"
#include "swell/scene/waves.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace {

using swell::Wave;
using swell::WaveSet;
using namespace swell::test::wave_sets;

using swell::kPi;

// The displacement written out directly from the definition in waves.h, in
// plain double: good near the origin and early in time.
glm::dvec3 naiveDisplacement(const WaveSet& set, glm::dvec2 x0, double t)
{
    glm::dvec3 sum(0.0);
    for (const Wave& w : set.waves) {
        const glm::dvec2 d = glm::normalize(w.direction);
        const double k = 2.0 * kPi / w.wavelength_m;
        const double omega = std::isinf(set.depth_m) ? std::sqrt(swell::kGravity * k)
                                                     : std::sqrt(swell::kGravity * k * std::tanh(k * set.depth_m));
        const double theta = k * glm::dot(d, x0) - omega * t + w.phase_rad;
        sum += glm::dvec3(-w.steepness * w.amplitude_m * d.x * std::sin(theta), w.amplitude_m * std::cos(theta),
                          -w.steepness * w.amplitude_m * d.y * std::sin(theta));
    }
    return sum;
}

// --- Dispersion ------------------------------------------------------------

TEST(Dispersion, DeepWaterPeriodOfA100mWave)
{
    // Deep water: T = sqrt(2*pi*wavelength/g), 8.0044 s for 100 m.
    const double k = 2.0 * kPi / 100.0;
    const double period = std::sqrt(2.0 * kPi * 100.0 / swell::kGravity);
    EXPECT_NEAR(swell::angularFrequency(k, kInf), 2.0 * kPi / period, 1e-12);
    EXPECT_NEAR(period, 8.0044, 1e-4);
}

TEST(Dispersion, DeepLimitOfFiniteDepth)
{
    const double k = 2.0 * kPi / 10.0;
    // tanh(k*h) = 1 to double precision once k*h > 19.
    EXPECT_DOUBLE_EQ(swell::angularFrequency(k, 1000.0), swell::angularFrequency(k, kInf));
}

TEST(Dispersion, ShallowWaterTravelsAtSqrtGH)
{
    // k*h = 1e-3: omega = k*sqrt(g*h) * (1 - (kh)^2/6 + ...).
    const double depth = 2.0;
    const double k = 1e-3 / depth;
    const double shallow = k * std::sqrt(swell::kGravity * depth);
    EXPECT_NEAR(swell::angularFrequency(k, depth) / shallow, 1.0, 1e-6);
    EXPECT_LT(swell::angularFrequency(k, depth), swell::angularFrequency(k, kInf));
}

TEST(Dispersion, IntermediateDepthValue)
{
    // 50 m waves in 5 m of water: omega^2 = g*k*tanh(k*h), k*h = 0.6283.
    const double k = 2.0 * kPi / 50.0;
    const double expected = std::sqrt(swell::kGravity * k * std::tanh(k * 5.0));
    EXPECT_NEAR(swell::angularFrequency(k, 5.0), expected, 1e-14);
    EXPECT_NEAR(expected, 0.8284, 1e-4); // by hand: sqrt(9.80665*0.125664*tanh(0.628319) = 0.556893)
}

TEST(Dispersion, CrestsMoveAtThePhaseSpeed)
{
    // One wave: the pattern at time t is the pattern at 0 shifted by c*t along d.
    for (double depth : {kInf, 3.0}) {
        WaveSet set;
        set.depth_m = depth;
        set.waves = {{{3.0, 4.0}, 25.0, 0.6, 0.8, 0.4}};
        const double k = 2.0 * kPi / 25.0;
        const double c = swell::angularFrequency(k, depth) / k;
        const glm::dvec2 d(0.6, 0.8);
        const double t = 7.3;
        for (glm::dvec2 x0 : randomPoints(20, 50.0, {0.0, 0.0}, 1)) {
            const glm::dvec3 later = swell::displacementAt(set, x0 + c * t * d, t);
            const glm::dvec3 now = swell::displacementAt(set, x0, 0.0);
            EXPECT_NEAR(later.x, now.x, 1e-12);
            EXPECT_NEAR(later.y, now.y, 1e-12);
            EXPECT_NEAR(later.z, now.z, 1e-12);
        }
    }
}

// --- The wave function -------------------------------------------------------

TEST(Displacement, MatchesTheDefinition)
{
    for (double depth : {kInf, 4.0}) {
        const WaveSet set = handSet(depth);
        for (glm::dvec2 x0 : randomPoints(50, 100.0, {0.0, 0.0}, 2)) {
            const glm::dvec3 expected = naiveDisplacement(set, x0, 3.25);
            const glm::dvec3 got = swell::displacementAt(set, x0, 3.25);
            EXPECT_NEAR(got.x, expected.x, 1e-12);
            EXPECT_NEAR(got.y, expected.y, 1e-12);
            EXPECT_NEAR(got.z, expected.z, 1e-12);
        }
    }
}

TEST(Displacement, SingleWaveByHand)
{
    // theta = k*x - omega*t + phase with k = 2*pi/10, at x = 2.5, t = 0, phase 0:
    // theta = pi/2, so sin = 1, cos = 0.
    WaveSet set;
    set.waves = {{{2.0, 0.0}, 10.0, 0.5, 0.8, 0.0}};
    const glm::dvec3 d = swell::displacementAt(set, {2.5, 7.0}, 0.0);
    EXPECT_NEAR(d.x, -0.8 * 0.5, 1e-15);
    EXPECT_NEAR(d.y, 0.0, 1e-15);
    EXPECT_NEAR(d.z, 0.0, 1e-15);
}

TEST(Displacement, EmptySetIsFlat)
{
    const WaveSet set;
    EXPECT_EQ(swell::displacementAt(set, {3.0, 4.0}, 5.0), glm::dvec3(0.0));
    EXPECT_EQ(swell::normalAt(set, {3.0, 4.0}, 5.0), glm::dvec3(0.0, 1.0, 0.0));
    EXPECT_EQ(swell::heightAt(set, {3.0, 4.0}, 5.0), 0.0);
}

TEST(Derivatives, MatchCentralDifferences)
{
    const WaveSet set = handSet(6.0);
    const double h = 1e-5; // truncation ~h^2*k^3*A ~ 1e-9, rounding ~1e-16/h ~ 1e-11
    for (glm::dvec2 x0 : randomPoints(40, 60.0, {0.0, 0.0}, 3)) {
        const swell::SurfacePartials p = swell::partialsAt(set, x0, 11.0);
        const glm::dvec3 fdX = (displacedPoint(set, x0 + glm::dvec2(h, 0.0), 11.0)
                                - displacedPoint(set, x0 - glm::dvec2(h, 0.0), 11.0))
                             / (2.0 * h);
        const glm::dvec3 fdZ = (displacedPoint(set, x0 + glm::dvec2(0.0, h), 11.0)
                                - displacedPoint(set, x0 - glm::dvec2(0.0, h), 11.0))
                             / (2.0 * h);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(p.alongX[c], fdX[c], 1e-7) << "component " << c;
            EXPECT_NEAR(p.alongZ[c], fdZ[c], 1e-7) << "component " << c;
        }
    }
}

TEST(Normals, MatchFiniteDifferenceNormals)
{
    const WaveSet set = handSet();
    const double h = 1e-5;
    for (glm::dvec2 x0 : randomPoints(40, 60.0, {0.0, 0.0}, 4)) {
        const glm::dvec3 tangent = displacedPoint(set, x0 + glm::dvec2(h, 0.0), 2.0)
                                 - displacedPoint(set, x0 - glm::dvec2(h, 0.0), 2.0);
        const glm::dvec3 binormal = displacedPoint(set, x0 + glm::dvec2(0.0, h), 2.0)
                                  - displacedPoint(set, x0 - glm::dvec2(0.0, h), 2.0);
        const glm::dvec3 expected = glm::normalize(glm::cross(binormal, tangent));
        const glm::dvec3 n = swell::normalAt(set, x0, 2.0);
        EXPECT_NEAR(glm::length(n), 1.0, 1e-14);
        EXPECT_GT(n.y, 0.0);
        EXPECT_NEAR(glm::distance(n, expected), 0.0, 1e-7);
    }
}

TEST(Normals, FlatSeaPointsUp)
{
    WaveSet set;
    set.waves = {{{1.0, 0.0}, 10.0, 0.0, 0.5, 0.0}};
    EXPECT_EQ(swell::normalAt(set, {1.0, 2.0}, 3.0), glm::dvec3(0.0, 1.0, 0.0));
}

// --- The inverse: height under a world point ---------------------------------

TEST(HeightAt, RoundTripsDisplacedRestPoints)
{
    // Displace a rest point, then ask for the height at its image.
    for (bool aligned : {false, true}) {
        for (int n : {1, 8, 64}) {
            const WaveSet set = randomFoldLimitedSet(n, 10 + n, aligned);
            EXPECT_LE(swell::foldMeasure(set), 1.0);
            EXPECT_GT(swell::foldMeasure(set), 0.999999);
            for (glm::dvec2 x0 : randomPoints(300, 200.0, {0.0, 0.0}, 5)) {
                const glm::dvec3 p = displacedPoint(set, x0, 13.0);
                const glm::dvec2 world(p.x, p.z);
                // Requirement: 0.1 mm. The solve gets to ~1e-9 m.
                EXPECT_NEAR(swell::heightAt(set, world, 13.0), p.y, 1e-7) << "n=" << n << " aligned=" << aligned;
                // At the fold limit the rest point itself is ill-conditioned
                // next to cusps; its image is not.
                const glm::dvec3 image = displacedPoint(set, swell::restPointUnder(set, world, 13.0), 13.0);
                EXPECT_NEAR(glm::distance(glm::dvec2(image.x, image.z), world), 0.0, 1e-9);
            }
        }
    }
}

TEST(HeightAt, FindsTheRestPointBelowTheLimit)
{
    WaveSet set = randomFoldLimitedSet(16, 99, true);
    for (Wave& w : set.waves)
        w.steepness *= 0.9;
    for (glm::dvec2 x0 : randomPoints(300, 200.0, {0.0, 0.0}, 15)) {
        const glm::dvec3 p = displacedPoint(set, x0, 1.0);
        EXPECT_NEAR(glm::distance(swell::restPointUnder(set, {p.x, p.z}, 1.0), x0), 0.0, 1e-9);
    }
}

TEST(HeightAt, RoundTripsFarAwayAndLate)
{
    const WaveSet set = randomFoldLimitedSet(32, 77, false);
    const glm::dvec2 far(3e5, -8e5);
    for (glm::dvec2 x0 : randomPoints(200, 500.0, far, 6)) {
        const glm::dvec3 p = displacedPoint(set, x0, 4e5);
        EXPECT_NEAR(swell::heightAt(set, {p.x, p.z}, 4e5), p.y, 1e-7);
    }
}

TEST(HeightAt, ConvergesNextToACusp)
{
    // One wave with Q*k*A = 1: a trochoid with cusps on its crests, where
    // the Jacobian is singular and the height is steepest in world space.
    WaveSet set;
    set.waves = {{{1.0, 0.0}, 20.0, 20.0 / (2.0 * kPi), 1.0, 0.0}};
    ASSERT_DOUBLE_EQ(swell::foldMeasure(set), 1.0);
    for (int i = -400; i <= 400; ++i) {
        const double x0 = i * 5e-3; // dense around the crest at x0 = 0
        const glm::dvec3 p = displacedPoint(set, {x0, 0.0}, 0.0);
        EXPECT_NEAR(swell::heightAt(set, {p.x, p.z}, 0.0), p.y, 1e-5) << "x0=" << x0;
    }
}

TEST(HeightAt, FiniteDepth)
{
    const WaveSet set = handSet(3.0);
    for (glm::dvec2 x0 : randomPoints(100, 50.0, {0.0, 0.0}, 7)) {
        const glm::dvec3 p = displacedPoint(set, x0, 5.0);
        EXPECT_NEAR(swell::heightAt(set, {p.x, p.z}, 5.0), p.y, 1e-7);
    }
}

// --- Phase precision far from the origin and late in time ---------------------

TEST(Phase, WrappedPhaseIsInRange)
{
    const WaveSet set = handSet();
    for (glm::dvec2 o : randomPoints(200, 1e7, {0.0, 0.0}, 8)) {
        for (const Wave& w : set.waves) {
            const double phase = swell::wrappedPhase(w, set.depth_m, o, 1e6);
            EXPECT_GE(phase, -kPi);
            EXPECT_LT(phase, kPi);
        }
    }
}

TEST(Phase, WrappedPhaseAtTheOriginIsThePhaseOffset)
{
    Wave w;
    w.phase_rad = 1.25;
    EXPECT_DOUBLE_EQ(swell::wrappedPhase(w, kInf, {0.0, 0.0}, 0.0), 1.25);
    w.phase_rad = 1.25 + 6.0 * kPi;
    EXPECT_NEAR(swell::wrappedPhase(w, kInf, {0.0, 0.0}, 0.0), 1.25, 1e-14);
}

TEST(Phase, MatchesExtendedPrecisionAt1e6)
{
    // The same definition evaluated in long double (64-bit mantissa on x86):
    // theta = kd.x*x + kd.z*z - omega*t + phase with the library's kd and omega.
    if (std::numeric_limits<long double>::digits < 64)
        GTEST_SKIP() << "long double is no wider than double here";
    const WaveSet set = handSet(8.0);
    for (glm::dvec2 o : randomPoints(50, 1e6, {0.0, 0.0}, 9)) {
        for (const Wave& w : set.waves) {
            const glm::dvec2 kd = swell::wavenumberVector(w);
            const double omega = swell::angularFrequency(2.0 * kPi / w.wavelength_m, set.depth_m);
            const long double t = 1e6L;
            const long double theta = static_cast<long double>(kd.x) * o.x + static_cast<long double>(kd.y) * o.y
                                    - static_cast<long double>(omega) * t + w.phase_rad;
            const long double twoPi = 6.283185307179586476925286766559L;
            long double ref = std::fmod(theta + twoPi / 2, twoPi);
            if (ref < 0)
                ref += twoPi;
            ref -= twoPi / 2;
            // |theta| ~ 1e7 rad: long double holds it to ~1e-12 rad.
            const double got = swell::wrappedPhase(w, set.depth_m, o, 1e6);
            double diff = static_cast<double>(got - ref);
            diff -= 2.0 * kPi * std::round(diff / (2.0 * kPi)); // -pi and pi are the same angle
            EXPECT_NEAR(diff, 0.0, 1e-10);
        }
    }
}

TEST(Phase, SplitFormAgreesFarFromTheOriginAndLate)
{
    // What the GPU does: theta = k*dot(d, x0 - origin) + wrappedPhase(origin),
    // with the origin at 1e6 m and t = 1e6 s.
    const WaveSet set = handSet(12.0);
    const double t = 1e6;
    for (glm::dvec2 origin : {glm::dvec2(1e6, -1e6), glm::dvec2(-7.3e5, 1e6 + 0.37)}) {
        for (glm::dvec2 x0 : randomPoints(100, 100.0, origin, 10)) {
            glm::dvec3 split(0.0);
            for (const Wave& w : set.waves) {
                const glm::dvec2 kd = swell::wavenumberVector(w);
                const glm::dvec2 d = glm::normalize(w.direction);
                const double theta = glm::dot(kd, x0 - origin) + swell::wrappedPhase(w, set.depth_m, origin, t);
                split += glm::dvec3(-w.steepness * w.amplitude_m * d.x * std::sin(theta),
                                    w.amplitude_m * std::cos(theta),
                                    -w.steepness * w.amplitude_m * d.y * std::sin(theta));
            }
            const glm::dvec3 direct = swell::displacementAt(set, x0, t);
            EXPECT_NEAR(direct.x, split.x, 1e-9);
            EXPECT_NEAR(direct.y, split.y, 1e-9);
            EXPECT_NEAR(direct.z, split.z, 1e-9);
        }
    }
}

TEST(Phase, TimeIsPeriodic)
{
    WaveSet set;
    set.waves = {{{1.0, 1.0}, 33.0, 1.1, 0.6, 0.2}};
    const double omega = swell::angularFrequency(2.0 * kPi / 33.0, kInf);
    const double period = 2.0 * kPi / omega;
    const glm::dvec3 a = swell::displacementAt(set, {4.0, -2.0}, 100.0);
    const glm::dvec3 b = swell::displacementAt(set, {4.0, -2.0}, 100.0 + 1000.0 * period);
    EXPECT_NEAR(glm::distance(a, b), 0.0, 1e-9);
}

// --- Fold limit ---------------------------------------------------------------

TEST(FoldLimit, MeasureIsSumOfQkA)
{
    const WaveSet set = handSet();
    double expected = 0.0;
    for (const Wave& w : set.waves)
        expected += w.steepness * 2.0 * kPi / w.wavelength_m * w.amplitude_m;
    EXPECT_NEAR(swell::foldMeasure(set), expected, 1e-15);
}

TEST(FoldLimit, FoldFreeSetIsLeftAlone)
{
    WaveSet set = handSet();
    ASSERT_LT(swell::foldMeasure(set), 1.0);
    const WaveSet before = set;
    EXPECT_EQ(swell::limitSteepness(set), "");
    for (std::size_t i = 0; i < set.waves.size(); ++i)
        EXPECT_EQ(set.waves[i].steepness, before.waves[i].steepness);
}

TEST(FoldLimit, ScalesEverySteepnessAndNamesTheBiggest)
{
    WaveSet set;
    set.waves = {
        {{1.0, 0.0}, 10.0, 0.5, 0.9, 0.0},  // Q*k*A = 0.283
        {{0.0, 1.0}, 4.0, 0.4, 1.0, 0.0},   // 0.628
        {{1.0, 1.0}, 2.0, 0.25, 0.8, 0.0},  // 0.628
        {{1.0, -1.0}, 50.0, 0.2, 0.5, 0.0}, // 0.0126
    };
    const double before = swell::foldMeasure(set);
    ASSERT_GT(before, 1.0);
    const WaveSet original = set;
    const std::string warning = swell::limitSteepness(set);
    EXPECT_LE(swell::foldMeasure(set), 1.0);
    EXPECT_NEAR(swell::foldMeasure(set), 1.0, 1e-12);
    for (std::size_t i = 0; i < set.waves.size(); ++i)
        EXPECT_NEAR(set.waves[i].steepness, original.waves[i].steepness / before, 1e-12);
    EXPECT_NE(warning.find("swell::limitSteepness()"), std::string::npos) << warning;
    EXPECT_NE(warning.find("wave 1 (wavelength 4 m, amplitude 0.4 m, Q 1)"), std::string::npos) << warning;
    EXPECT_NE(warning.find("wave 2 (wavelength 2 m"), std::string::npos) << warning;
    EXPECT_NE(warning.find("wave 0 (wavelength 10 m"), std::string::npos) << warning;
    EXPECT_EQ(warning.find("wave 3"), std::string::npos) << warning;
}

TEST(FoldLimit, ManyLimitedSetsStayAtOrBelowOne)
{
    for (std::uint32_t seed = 0; seed < 200; ++seed) {
        const WaveSet set = randomFoldLimitedSet(1 + static_cast<int>(seed % 64), seed, seed % 2 == 0);
        EXPECT_LE(swell::foldMeasure(set), 1.0) << "seed " << seed;
    }
}

TEST(FoldLimit, OverflowingMeasureGivesFlatCrestsNotNaN)
{
    WaveSet set;
    set.waves = {{{1.0, 0.0}, 1e-300, 1e300, 1.0, 0.0}, {{0.0, 1.0}, 10.0, 1.0, 1.0, 0.0}};
    ASSERT_TRUE(std::isinf(swell::foldMeasure(set)));
    EXPECT_NE(swell::limitSteepness(set), "");
    EXPECT_EQ(swell::foldMeasure(set), 0.0);
    for (const Wave& w : set.waves)
        EXPECT_EQ(w.steepness, 0.0);
}

TEST(FoldLimit, InvalidSetIsReportedNotChanged)
{
    WaveSet set = handSet();
    set.waves[1].amplitude_m = std::numeric_limits<double>::quiet_NaN();
    const std::string warning = swell::limitSteepness(set);
    EXPECT_NE(warning.find("wave 1: amplitude_m must be finite"), std::string::npos) << warning;
    EXPECT_EQ(set.waves[0].steepness, handSet().waves[0].steepness);
}

// --- Validation ---------------------------------------------------------------

TEST(Validate, AcceptsGoodSets)
{
    EXPECT_EQ(swell::validate(handSet()), "");
    EXPECT_EQ(swell::validate(handSet(0.5)), "");
    EXPECT_EQ(swell::validate(WaveSet{}), "");
    WaveSet full;
    full.waves.resize(SWELL_MAX_WAVES);
    EXPECT_EQ(swell::validate(full), "");
}

TEST(Validate, NamesTheWaveAndTheField)
{
    struct Case {
        void (*breakIt)(WaveSet&);
        const char* message;
    };
    const Case cases[] = {
        {[](WaveSet& s) { s.waves[3].wavelength_m = -1.0; }, "wave 3: wavelength_m must be > 0 (got -1)"},
        {[](WaveSet& s) { s.waves[0].wavelength_m = 0.0; }, "wave 0: wavelength_m must be > 0 (got 0)"},
        {[](WaveSet& s) { s.waves[2].wavelength_m = kInf; }, "wave 2: wavelength_m must be finite (got inf)"},
        {[](WaveSet& s) { s.waves[1].wavelength_m = 1e-320; },
         "wave 1: wavelength_m is too small, its wavenumber overflows (got 1e-320)"},
        {[](WaveSet& s) { s.waves[1].amplitude_m = -0.5; }, "wave 1: amplitude_m must be >= 0 (got -0.5)"},
        {[](WaveSet& s) { s.waves[1].amplitude_m = std::numeric_limits<double>::quiet_NaN(); },
         "wave 1: amplitude_m must be finite (got nan)"},
        {[](WaveSet& s) { s.waves[2].steepness = 1.5; }, "wave 2: steepness must be in 0..1 (got 1.5)"},
        {[](WaveSet& s) { s.waves[2].steepness = -0.1; }, "wave 2: steepness must be in 0..1 (got -0.1)"},
        {[](WaveSet& s) { s.waves[2].steepness = std::numeric_limits<double>::quiet_NaN(); },
         "wave 2: steepness must be in 0..1 (got nan)"},
        {[](WaveSet& s) { s.waves[0].phase_rad = -kInf; }, "wave 0: phase_rad must be finite (got -inf)"},
        {[](WaveSet& s) { s.waves[3].direction = {0.0, 0.0}; },
         "wave 3: direction must be finite and non-zero (got (0, 0))"},
        {[](WaveSet& s) { s.waves[3].direction = {1.0, std::numeric_limits<double>::quiet_NaN()}; },
         "wave 3: direction must be finite and non-zero (got (1, nan))"},
        {[](WaveSet& s) { s.depth_m = 0.0; }, "depth_m must be > 0 or infinity (got 0)"},
        {[](WaveSet& s) { s.depth_m = -kInf; }, "depth_m must be > 0 or infinity (got -inf)"},
        {[](WaveSet& s) { s.depth_m = std::numeric_limits<double>::quiet_NaN(); },
         "depth_m must be > 0 or infinity (got nan)"},
        {[](WaveSet& s) { s.waves.resize(SWELL_MAX_WAVES + 1); },
         "65 waves, at most 64 (SWELL_MAX_WAVES) are supported"},
    };
    for (const Case& c : cases) {
        WaveSet set = handSet();
        c.breakIt(set);
        EXPECT_EQ(swell::validate(set), c.message);
    }
}

// --- Extreme but accepted parameters -------------------------------------------

void expectFinite(glm::dvec3 v, const char* what)
{
    EXPECT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z)) << what;
}

TEST(Extremes, NoNaNForTinyWavesHugeAmplitudesAndLateTimes)
{
    WaveSet set;
    set.waves = {
        {{1.0, 0.0}, 1e-6, 1e-7, 1.0, 0.0},  // tiny wave
        {{0.0, 1.0}, 10.0, 1e6, 1.0, 0.0},   // huge amplitude, steepness limited below
        {{1.0, 1.0}, 1e6, 10.0, 1.0, 3.0},   // very long wave
        {{-1.0, 0.3}, 0.01, 1e-3, 0.2, 1.0}, // short
    };
    set.depth_m = 0.01; // very shallow for the long ones
    ASSERT_EQ(swell::validate(set), "");
    swell::limitSteepness(set);
    ASSERT_EQ(swell::validate(set), "");
    for (double t : {0.0, 1e6, 1e9}) {
        for (glm::dvec2 x0 : {glm::dvec2(0.0), glm::dvec2(1e6, -1e6), glm::dvec2(3.7, 1e9)}) {
            expectFinite(swell::displacementAt(set, x0, t), "displacementAt");
            const glm::dvec3 n = swell::normalAt(set, x0, t);
            expectFinite(n, "normalAt");
            EXPECT_NEAR(glm::length(n), 1.0, 1e-12);
            EXPECT_TRUE(std::isfinite(swell::heightAt(set, x0, t)));
            const glm::dvec2 r = swell::restPointUnder(set, x0, t);
            EXPECT_TRUE(std::isfinite(r.x) && std::isfinite(r.y));
            EXPECT_TRUE(std::isfinite(swell::wrappedPhase(set.waves[0], set.depth_m, x0, t)));
        }
    }
}

TEST(Extremes, HugeAmplitudeRoundTrip)
{
    // 1 km amplitude on a 10 km wave, at the fold limit: the solve's tolerance
    // scales with the amplitudes.
    WaveSet set;
    set.waves = {{{1.0, 0.0}, 1e4, 1e3, 1.0, 0.0}, {{0.3, 1.0}, 3e3, 2e2, 1.0, 1.0}};
    swell::limitSteepness(set);
    for (glm::dvec2 x0 : randomPoints(50, 1e4, {0.0, 0.0}, 11)) {
        const glm::dvec3 p = displacedPoint(set, x0, 100.0);
        EXPECT_NEAR(swell::heightAt(set, {p.x, p.z}, 100.0), p.y, 1e-6);
    }
}

} // namespace
