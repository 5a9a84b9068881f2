// The spectral ocean's world-space foam (src/ocean/spectral/world_foam.h):
// its windows put every world texel where the lookup reads it, far from the
// origin too, and its fold threshold makes foam on the fraction of the sea
// asked for.
#include "ocean/spectral/spectral_cpu.h"
#include "ocean/spectral/whitecaps.h"
#include "ocean/spectral/world_foam.h"
#include "swell/scene/spectrum.h"

#include <gtest/gtest.h>

#include <cmath>
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

// The threshold is a quantile of the field's Jacobian; at other points and
// another time, the share of the sea below it must be the share asked for.
TEST(WorldFoam, TheFoldThresholdMakesFoamOnTheBreakingFraction)
{
    WindSettings wind;
    wind.windSpeed_mps = 14.0;
    wind.fetch_km = 3000.0;
    const auto field = std::make_shared<const SpectralField>(makeSpectralField(SeaSpectrum(wind), 1.0, 5));
    const CpuSurface cpu(field);
    const double fraction = breakingFraction(wind.windSpeed_mps);
    const float threshold = foldThresholdFor(cpu, *field, fraction);
    EXPECT_LT(threshold, 1.0f); // folds are compressions
    int below = 0, total = 0;
    const double spacing_m = 2.71 * field->cascades[0].patch_m / 256.0;
    for (int row = 0; row < 200; ++row)
        for (int col = 0; col < 200; ++col) {
            below += cpu.foldJacobianAt({5000.0 + col * spacing_m, -700.0 + row * spacing_m}, 333.0, SurfaceFilter{},
                                        kFoamCascades) < threshold;
            ++total;
        }
    const double share = double(below) / total;
    std::printf("breaking fraction %.4f, share below the threshold elsewhere %.4f\n", fraction, share);
    EXPECT_NEAR(share, fraction, 0.25 * fraction);
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
