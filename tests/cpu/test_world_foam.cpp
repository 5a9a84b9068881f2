// The spectral ocean's world-space foam (src/ocean/spectral/world_foam.h):
// its windows put every world texel where the lookup reads it, far from the
// origin too, and its breaking ramp makes foam on the fraction of the sea
// asked for, in every stretch of it.
#include "ocean/spectral/breaking.h"
#include "ocean/spectral/spectral_cpu.h"
#include "ocean/spectral/whitecaps.h"
#include "ocean/spectral/world_foam.h"
#include "swell/scene/spectrum.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

namespace {

using namespace swell;
using namespace swell::spectral;

double positiveModulo(double v, double n) { return v - n * std::floor(v / n); }

// The compute shader writes world texel w at w mod N, its centre at rest
// offset (w - centreIndex + 0.5 - centreFraction) * texel from the grid
// centre; worldFoam() reads rest offset r at texel originTexels + r / texel
// (mod N). The two must meet at the texel's centre, wherever the centre is.
TEST(WorldFoam, TheLookupReadsEachTexelAtItsCentre)
{
    const double texel_m = 0.8125;
    for (const glm::dvec2 centre : {glm::dvec2(0.0, 0.0), glm::dvec2(-37.3, 1234.9), glm::dvec2(1.0e7 + 0.3, -2.5e6)}) {
        const FoamWindow w = foamWindowAt(centre, texel_m);
        EXPECT_EQ(w.origin, w.centreIndex - glm::ivec2(kFoamSize / 2));
        EXPECT_GE(w.centreFraction.x, 0.0f);
        EXPECT_LT(w.centreFraction.x, 1.0f);
        for (const int offset : {-kFoamSize / 2, -1, 0, 7, kFoamSize / 2 - 1}) {
            // World texel index relative to the centre's (what the shader
            // computes from wrapped indices).
            const glm::dvec2 restOffset_m =
                (glm::dvec2(offset, -offset) + 0.5 - glm::dvec2(w.centreFraction)) * texel_m;
            const glm::dvec2 lookup = glm::dvec2(w.originTexels) + restOffset_m / texel_m;
            const glm::dvec2 worldIndex = glm::floor(centre / texel_m) + glm::dvec2(offset, -offset);
            for (int axis = 0; axis < 2; ++axis) {
                const double stored = positiveModulo(worldIndex[axis], kFoamSize);
                const double read = positiveModulo(lookup[axis], kFoamSize);
                // Float uniforms far from the origin: within a hundredth of a texel.
                EXPECT_NEAR(read, stored + 0.5, 0.01) << "centre " << centre.x << ", " << centre.y << " offset " << offset;
            }
        }
    }
}

// The breaking score (breaking.h) is J against its own box, so its lowest
// share is the same everywhere: with the threshold at a quantile of the
// scores of one wide square, the share of another wide square, elsewhere
// and later, below it must be the quantile, and in a stretch of sea a
// camera 10 m up sees most of (a square of 24 x 24 level-0 texels), at
// every other second of a minute, within a factor of 2 of it: J against
// the whole sea held the storm's breaking share in such a stretch to no
// factor of 10 (0.03 to 10.5 times it, measured on the CPU twin). The
// scores are the texels' own, before the spread (which makes each
// breaking a 3 x 3 patch, so a small square's count comes in nines).
std::vector<float> scores(const CpuSurface& cpu, const SpectralField& field, glm::dvec2 corner_m, int side,
                          double time_s)
{
    const int span = side + 2 * kBreakingRadius;
    const double texel_m = foamTexel_m(field, 0);
    std::vector<float> j(size_t(span) * size_t(span));
    for (int z = 0; z < span; ++z)
        for (int x = 0; x < span; ++x)
            j[size_t(z) * size_t(span) + size_t(x)] = float(
                cpu.foldJacobianAt(corner_m + glm::dvec2(x, z) * texel_m, time_s, SurfaceFilter{}, kFoamCascades));
    std::vector<float> s;
    for (int z = 0; z < side; ++z)
        for (int x = 0; x < side; ++x)
            s.push_back(breakingScore(&j[size_t(z) * size_t(span) + size_t(x)], span));
    return s;
}

double shareBelow(const std::vector<float>& values, float threshold)
{
    return double(std::count_if(values.begin(), values.end(), [threshold](float v) { return v < threshold; })) /
           double(values.size());
}

TEST(WorldFoam, TheBreakingScoresLowestShareIsTheSameEverywhere)
{
    WindSettings wind;
    wind.windSpeed_mps = 20.0;
    wind.fetch_km = 600.0; // the storm's
    const auto field = std::make_shared<const SpectralField>(makeSpectralField(SeaSpectrum(wind), 1.2, 13));
    const CpuSurface cpu(field);
    // A share large enough to count in a small square (about 20 of its 576
    // texels; a count of 3 is noise whatever the score).
    constexpr double kShare = 0.0343;
    std::vector<float> here = scores(cpu, *field, {0.0, 0.0}, 200, 0.0);
    std::nth_element(here.begin(), here.begin() + std::ptrdiff_t(kShare * double(here.size())), here.end());
    const float threshold = here[size_t(kShare * double(here.size()))];
    const double elsewhere = shareBelow(scores(cpu, *field, {5000.0, -700.0}, 200, 333.0), threshold);
    std::printf("share %.4f below the threshold here, %.4f elsewhere and later\n", kShare, elsewhere);
    EXPECT_NEAR(elsewhere, kShare, 0.25 * kShare);
    double lowest = 1.0, highest = 0.0;
    for (double t = 0.0; t < 60.0; t += 2.0) {
        const double s = shareBelow(scores(cpu, *field, {-22.0, -50.0}, 24, t), threshold);
        lowest = std::min(lowest, s);
        highest = std::max(highest, s);
    }
    std::printf("in one 24-texel square over a minute: %.4f to %.4f\n", lowest, highest);
    EXPECT_GT(lowest, kShare / 2.0);
    EXPECT_LT(highest, kShare * 2.0);
}

} // namespace

namespace {

// A still's replay plan (foamReplayOffsets_s): 2.5 lifetimes on the 0.5 s
// lattice a sequence of frames takes, strictly decreasing to 0, whatever
// the lifetime (20 steps at the salt-water 3.85 s, which the golden test
// was measured on).
TEST(WorldFoam, AStillsReplayIsOnTheSequencesLattice)
{
    for (const double lifetime_s : {0.5, 3.85, 10.0, 60.0}) {
        SCOPED_TRACE(lifetime_s);
        const std::vector<double> offsets = foamReplayOffsets_s(lifetime_s);
        ASSERT_FALSE(offsets.empty());
        EXPECT_EQ(offsets.back(), 0.0);
        EXPECT_GE(offsets.front(), kFoamReplayLifetimes * lifetime_s);
        for (std::size_t i = 1; i < offsets.size(); ++i) {
            EXPECT_EQ(offsets[i - 1] - offsets[i], kFoamReplayStep_s) << "at " << offsets[i];
        }
    }
    EXPECT_EQ(foamReplayOffsets_s(3.85).size(), 21u);
}

} // namespace
