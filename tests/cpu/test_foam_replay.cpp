// The CPU replay of a still's foam history (src/ocean/spectral/foam_replay.h)
// against the CPU twin of the surface: its fold Jacobian at each stored
// texel is the twin's at the texel's world point (through the windows'
// storage, the warp, the packed transforms and the phasors turned step by
// step), and its foam is max(decayed foam, made) of the twin's Jacobians.
// (Against the GPU's steps: Whitecaps.AStillShowsTheFoamItsHistoryMade.)
#include "ocean/spectral/foam_replay.h"
#include "ocean/spectral/spectral_cpu.h"
#include "ocean/spectral/whitecaps.h"
#include "ocean/spectral/world_foam.h"
#include "swell/scene/spectrum.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

namespace {

using namespace swell;
using namespace swell::spectral;

constexpr float kSoftness = 0.03f;

struct Replayed {
    std::shared_ptr<const SpectralField> field;
    glm::dvec2 centre_m{1234.5, -987.25};
    std::array<FoamWindow, kFoamLevels> windows{};
    float threshold = 0.0f;
};

Replayed replayedSea()
{
    WindSettings wind;
    wind.windSpeed_mps = 16.0;
    wind.fetch_km = 3000.0;
    Replayed r;
    r.field = std::make_shared<const SpectralField>(makeSpectralField(SeaSpectrum(wind), 1.0, 7));
    for (int level = 0; level < kFoamLevels; ++level)
        r.windows[size_t(level)] = foamWindowAt(r.centre_m, foamTexel_m(*r.field, level));
    r.threshold = foldThresholdFor(CpuSurface(r.field), *r.field, breakingFraction(wind.windSpeed_mps));
    return r;
}

// The world point a level's stored texel (x, z) holds.
glm::dvec2 texelPoint(const Replayed& r, const SpectralField& field, int level, int x, int z)
{
    const FoamWindow& w = r.windows[size_t(level)];
    const glm::ivec2 world = w.origin + ((glm::ivec2(x, z) - w.origin) & (kFoamSize - 1));
    return r.centre_m + (glm::dvec2(world - w.centreIndex) + 0.5 - glm::dvec2(w.centreFraction)) * foamTexel_m(field, level);
}

TEST(FoamReplay, ItsJacobianIsTheTwinsAfterTurnedPhasors)
{
    const Replayed r = replayedSea();
    const CpuSurface cpu(r.field);
    FoamReplay replay(r.field, r.threshold, kSoftness);
    // The last time reached by turning the first's phasors 6 times.
    replay.run(r.centre_m, r.windows, {17.0, 17.5, 18.0, 18.5, 19.0, 19.5, 20.0}, 3.85);
    double largest = 0.0;
    for (int level = 0; level < kFoamLevels; ++level)
        for (int z = 0; z < kFoamSize; z += 17)
            for (int x = 0; x < kFoamSize; x += 13) {
                const double twin = cpu.foldJacobianAt(texelPoint(r, *r.field, level, x, z), 20.0, {}, kFoamCascades);
                largest = std::max(largest, std::abs(double(replay.lastJacobian(level, x, z)) - twin));
            }
    // Float fields against the twin's (float fields, double sums): J spans
    // about 0.5 .. 1.5 here; a wrong texel, cascade or time is off by tenths.
    EXPECT_LT(largest, 2e-4);
}

TEST(FoamReplay, ItsFoamIsTheDecayedMaximumOfWhatTheFoldsMade)
{
    const Replayed r = replayedSea();
    const CpuSurface cpu(r.field);
    FoamReplay replay(r.field, r.threshold, kSoftness);
    const std::vector<double> times_s{30.0, 30.5, 31.0, 31.5, 32.0};
    const double lifetime_s = 3.85;
    const auto& foam = replay.run(r.centre_m, r.windows, times_s, lifetime_s);
    const double decay = std::exp(-0.5 / lifetime_s);
    struct Probe {
        int level, x, z;
        glm::dvec2 point_m;
        double expected = 0.0;
    };
    std::vector<Probe> probes;
    for (int level = 0; level < kFoamLevels; ++level)
        for (int z = 0; z < kFoamSize; z += 5)
            for (int x = 0; x < kFoamSize; x += 7)
                probes.push_back({level, x, z, texelPoint(r, *r.field, level, x, z)});
    // Time by time: the twin transforms its fields once per time.
    for (const double t : times_s)
        for (Probe& p : probes) {
            const double j = cpu.foldJacobianAt(p.point_m, t, {}, kFoamCascades);
            const double made = std::clamp(1.0 - (j - r.threshold) / kSoftness, 0.0, 1.0);
            p.expected = std::max(p.expected * decay, made);
        }
    int foamy = 0;
    for (const Probe& p : probes) {
        const double got = foam[size_t(p.level)][size_t(p.z) * kFoamSize + size_t(p.x)];
        // J within 2e-4 makes foam within 2e-4 / 0.03 (and the replay's
        // margin takes 0.0033 off); the half's rounding toward zero takes at
        // most 2^-11 of it a step.
        EXPECT_NEAR(got, p.expected, 0.01) << "level " << p.level << " texel " << p.x << ", " << p.z;
        foamy += got > 0.1;
    }
    EXPECT_GT(foamy, 20) << "too little foam to compare";
}

} // namespace
