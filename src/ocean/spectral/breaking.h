// Where the spectral ocean's whitecaps break: the breaking score of a texel
// against its neighbourhood (swell/gpu/breaking.h says why), computed as
// shaders/ocean/spectral_foam.comp computes it, and the ramp of scores
// that makes foam in full on a given share of the sea.
#pragma once

#include "ocean/spectral/spectral_cpu.h"
#include "ocean/spectral/spectral_field.h"
#include "ocean/spectral/world_foam.h"
#include "swell/gpu/breaking.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace swell::spectral {

inline constexpr int kBreakingRadius = SWELL_FOAM_BREAKING_RADIUS;
inline constexpr float kLeastBreakingDeviation = float(SWELL_FOAM_LEAST_DEVIATION);
// The ramp's span, in score: a fifth of the score's spread from its median
// to its lowest 1e-4 (about 1.7; the sea-wide J threshold's softness was a
// fifth of J's spread likewise).
inline constexpr float kBreakingSpan = 0.35f;

// The score of the texel at the centre of the box whose first texel is at
// `box`, rows `stride` floats apart: (J - mean) / max(deviation, least), in
// the shader's order of sums (float, row by row), so the two agree to
// their J's rounding.
inline float breakingScore(const float* box, int stride)
{
    constexpr int side = 2 * kBreakingRadius + 1;
    float sum = 0.0f;
    for (int dz = 0; dz < side; ++dz)
        for (int dx = 0; dx < side; ++dx)
            sum += box[dz * stride + dx];
    constexpr float count = float(side * side);
    const float mean = sum / count;
    float squares = 0.0f;
    for (int dz = 0; dz < side; ++dz)
        for (int dx = 0; dx < side; ++dx) {
            const float d = box[dz * stride + dx] - mean;
            squares += d * d;
        }
    const float deviation = std::max(std::sqrt(squares / count), kLeastBreakingDeviation);
    return (box[kBreakingRadius * stride + kBreakingRadius] - mean) / deviation;
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

// The ramp on which `fraction` of the sea makes foam in full: below the
// score's quantile `fraction`, fading out kBreakingSpan above it (the rim
// of a breaking makes partial foam, which the shading draws as lace, so a
// whitecap's edge is ragged rather than cut out along a contour). The
// scores are those of 64 blocks of 32^2 level-0 texels (each with its
// box's margin), sampled from the CPU twin at t = 0 (the score's
// statistics do not change with time, nor from place to place: that is
// its point) at the shader's warped points, the blocks spread over more
// than the largest patch, at each level's texel spacing.
// One ramp a foam level: a level's texels sample J more sparsely (level 1
// at two samples to cascade 1's shortest wave), so its scores spread wider
// (with level 0's ramp, the 8 m/s sea seen from 300 m, most of it level
// 1's, was 0.30 white against Monahan's 0.0046).
using BreakingRamps = std::array<BreakingRamp, kFoamLevels>;
BreakingRamps breakingRampsFor(const CpuSurface& cpu, const SpectralField& field, double fraction);

// The ramps of these starts (the constant span).
BreakingRamps breakingRampsStartingAt(const std::array<float, kFoamLevels>& starts);

} // namespace swell::spectral
