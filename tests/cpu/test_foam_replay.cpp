// The CPU replay of a still's foam history (src/ocean/spectral/foam_replay.h)
// against the CPU twin of the surface: its fold Jacobian at each stored
// texel is the twin's at the texel's world point (through the windows'
// storage, the warp, the packed transforms and the phasors turned step by
// step), and its foam is max(decayed foam, made) of the breaking scores of
// the twin's Jacobians (breaking.h).
// (Against the GPU's steps: Whitecaps.AStillShowsTheFoamItsHistoryMade.)
#include "ocean/spectral/breaking.h"
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

struct Replayed {
    std::shared_ptr<const SpectralField> field;
    glm::dvec2 centre_m{1234.5, -987.25};
    std::array<FoamWindow, kFoamLevels> windows{};
    BreakingRamps ramps{};
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
    r.ramps = calibratedBreakingRamps(r.field, wind.windSpeed_mps);
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
    FoamReplay replay(r.field, r.ramps);
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
    FoamReplay replay(r.field, r.ramps);
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
        for (int z = 0; z < kFoamSize; z += 9)
            for (int x = 0; x < kFoamSize; x += 11)
                probes.push_back({level, x, z, texelPoint(r, *r.field, level, x, z)});
    // Time by time: the twin transforms its fields once per time. Each
    // probe's foam from the twin's J: the most any box within the level's
    // spread makes (the score of each box around its own centre).
    constexpr int kSide = 2 * kBreakingRadius + 1;
    for (const double t : times_s)
        for (Probe& p : probes) {
            const double texel_m = foamTexel_m(*r.field, p.level);
            const int spread = breakingSpreadAt(p.level), span = kSide + 2 * spread;
            std::vector<float> jacobian(size_t(span) * size_t(span));
            for (int dz = 0; dz < span; ++dz)
                for (int dx = 0; dx < span; ++dx)
                    jacobian[size_t(dz * span + dx)] = float(cpu.foldJacobianAt(
                        p.point_m + glm::dvec2(dx - kBreakingRadius - spread, dz - kBreakingRadius - spread) * texel_m,
                        t, {}, kFoamCascades));
            double made = 0.0;
            for (int dz = 0; dz <= 2 * spread; ++dz)
                for (int dx = 0; dx <= 2 * spread; ++dx)
                    made = std::max(made, double(foamMadeAt(breakingScore(&jacobian[size_t(dz * span + dx)], span),
                                                            r.ramps[size_t(p.level)].start,
                                                            r.ramps[size_t(p.level)].span)));
            p.expected = std::max(p.expected * decay, made);
        }
    int foamy = 0;
    for (const Probe& p : probes) {
        const double got = foam[size_t(p.level)][size_t(p.z) * kFoamSize + size_t(p.x)];
        // J within 2e-4 moves a score by up to about 3 * 2e-4 / deviation,
        // 0.012 where a box's deviation is 0.05, foam by that over the
        // ramp's span (kBreakingSpan, 0.15) where the J's differ most (most
        // differ far less), and the replay's margin takes 0.003 / 0.15
        // off; the half's rounding toward zero takes at most 2^-11 of it a
        // step.
        EXPECT_NEAR(got, p.expected, 0.05) << "level " << p.level << " texel " << p.x << ", " << p.z;
        foamy += got > 0.1;
    }
    EXPECT_GT(foamy, 10) << "too little foam to compare";
}

} // namespace
