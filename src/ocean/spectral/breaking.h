// Where the spectral ocean's whitecaps break: the breaking score of a texel
// against its neighbourhood (swell/gpu/breaking.h says why), computed as
// shaders/ocean/spectral_foam.comp computes it, and the ramps of scores on
// which a sea's foam covers Monahan's share of it.
#pragma once

#include "ocean/spectral/spectral_field.h"
#include "ocean/spectral/world_foam.h"
#include "swell/gpu/breaking.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

namespace swell::spectral {

inline constexpr int kBreakingRadius = SWELL_FOAM_BREAKING_RADIUS;
inline constexpr int kBreakingSpread = SWELL_FOAM_BREAKING_SPREAD;
// How many texels each way a level's breaking spreads its foam (level 0's
// kBreakingSpread, none at the coarser levels: swell/gpu/breaking.h says
// why), as spectral_foam.comp spreads it.
inline constexpr int breakingSpreadAt(int level) { return SWELL_FOAM_BREAKING_SPREAD_AT(level); }
inline constexpr float kLeastBreakingDeviation = float(SWELL_FOAM_LEAST_DEVIATION);
// The ramp's span, in score: narrow, so a breaking's own foam is full and
// dense. At 0.35 the trade wind (9 m/s) found its cover in the ramp's rim
// alone, no texel's foam above 0.53 and no breaking drawn dense; at 0.05 a
// still's replay on the CPU strayed from the GPU's steps by more than their
// J's rounding allows (FoamReplay.ItsFoamIsTheDecayedMaximumOfWhatTheFoldsMade,
// Whitecaps.AStillShowsTheFoamItsHistoryMade). At 0.15, 54 of the trade
// wind's 65536 level-0 texels were over a breaking's second-old amount in
// a still at t = 0.
inline constexpr float kBreakingSpan = 0.15f;

// The score of the texel at the centre of the box whose first texel is at
// `box`, rows `stride` floats apart: (J - mean) / max(deviation, least), in
// the shader's order of sums, so the two agree to their J's rounding: each
// row's sums of J - 1 and of its square (the shader shares a row's sums
// among the boxes across it, which is what makes the step cheap), then the
// rows'. J - 1 rather than J: J is near 1, so the mean of squares less the
// square of the mean keeps its digits (J spreads by a tenth or more where
// a box breaks; a glassier box's deviation is held at the least anyway).
inline float breakingScore(const float* box, int stride)
{
    constexpr int side = 2 * kBreakingRadius + 1;
    float sum = 0.0f, squares = 0.0f;
    for (int dz = 0; dz < side; ++dz) {
        float rowSum = 0.0f, rowSquares = 0.0f;
        for (int dx = 0; dx < side; ++dx) {
            const float d = box[dz * stride + dx] - 1.0f;
            rowSum += d;
            rowSquares += d * d;
        }
        sum += rowSum;
        squares += rowSquares;
    }
    constexpr float count = float(side * side);
    const float mean = sum / count;
    const float variance = std::max(squares / count - mean * mean, 0.0f);
    const float deviation = std::max(std::sqrt(variance), kLeastBreakingDeviation);
    return (box[kBreakingRadius * stride + kBreakingRadius] - 1.0f - mean) / deviation;
}

// Foam made at a score: none from `start` up, rising linearly below it to
// full `span` further down (spectral_foam.comp's).
inline float foamMadeAt(float score, float start, float span)
{
    return std::clamp((start - score) / span, 0.0f, 1.0f);
}

// Where foam is made: below `start`, full at start - span.
struct BreakingRamp {
    float start = 0.0f, span = 1.0f;
};

// The ramps on which a still's foam covers Monahan & O'Muircheartaigh's
// (1980) share of this sea at this wind, at the salt-water lifetime: found
// on the CPU twin by a still's replay (FoamReplay's lowest scores, both
// windows, 20 steps) and a bisection of the score of full foam, the cover
// counted through the look's share (foam::foamShare). Each level its own
// ramp: a level's texels sample J more sparsely (level 1 at two samples to
// cascade 1's shortest wave) and it spreads none, so its scores differ.
// A fixed share of the sea breaking with a cover fitted over winds (the
// last design) missed by the sea's shape: the storm's wide spread and its
// seed gave half the cover of the calibration's sea at the same wind.
// Found once per sea and wind in a process (about 0.4 s of CPU), then kept.
using BreakingRamps = std::array<BreakingRamp, kFoamLevels>;
BreakingRamps calibratedBreakingRamps(std::shared_ptr<const SpectralField> field, double windSpeed10_mps);

// The ramps of these starts (the constant span).
BreakingRamps breakingRampsStartingAt(const std::array<float, kFoamLevels>& starts);

} // namespace swell::spectral
