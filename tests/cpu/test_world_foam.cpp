// The spectral ocean's world-space foam (src/ocean/spectral/world_foam.h):
// its windows put every world texel where the lookup reads it, far from the
// origin too, and its fold threshold makes foam on the fraction of the sea
// asked for.
#include "ocean/spectral/spectral_cpu.h"
#include "ocean/spectral/whitecaps.h"
#include "ocean/spectral/world_foam.h"
#include "swell/spectrum.h"

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

// A still's replay plan (foamReplayOffsets_s): at the salt-water lifetime
// the whole 2.5 lifetimes every 0.5 s, as before the plan grew; at the
// longest lifetime (60 s) the same 2.5 lifetimes (150 s) in at most
// kFoamReplayMostSteps steps, the last 10 s still every 0.5 s; every offset
// on the sequence's lattice, strictly decreasing to 0.
TEST(WorldFoam, AStillsReplayIsBoundedAndOnTheSequencesLattice)
{
    for (const double lifetime_s : {0.5, 3.85, 10.0, 30.0, 60.0}) {
        SCOPED_TRACE(lifetime_s);
        const std::vector<double> offsets = foamReplayOffsets_s(lifetime_s);
        ASSERT_FALSE(offsets.empty());
        EXPECT_EQ(offsets.back(), 0.0);
        EXPECT_EQ(offsets.front(), std::ceil(kFoamReplayLifetimes * lifetime_s / kFoamReplayStep_s) * kFoamReplayStep_s);
        EXPECT_LE(offsets.size(), std::size_t(kFoamReplayMostSteps + 1));
        for (std::size_t i = 0; i < offsets.size(); ++i) {
            const double steps = offsets[i] / kFoamReplayStep_s;
            EXPECT_EQ(steps, std::round(steps)) << "off the lattice: " << offsets[i];
            if (i > 0) {
                EXPECT_LT(offsets[i], offsets[i - 1]);
            }
            // The last kFoamFineReplay_s every step of the lattice.
            if (offsets[i] <= kFoamFineReplay_s && i + 1 < offsets.size()) {
                EXPECT_EQ(offsets[i] - offsets[i + 1], kFoamReplayStep_s) << "at " << offsets[i];
            }
        }
    }
    // The default lifetime's replay is the one the golden test was measured on.
    EXPECT_EQ(foamReplayOffsets_s(3.85).size(), 21u);
    // The longest lifetime's no dearer than twice the default's.
    EXPECT_LE(foamReplayOffsets_s(60.0).size() - 1, 2 * (foamReplayOffsets_s(3.85).size() - 1));
}

} // namespace
