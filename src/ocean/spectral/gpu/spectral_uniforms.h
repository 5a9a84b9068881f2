// The spectral model's std140 uniform block (SpectralCascades, read by
// shaders/ocean/spectral.glsl): the C++ struct and its description
// (gl/block_layout.h), from which gpu/spectral_block.glsl is generated at
// build time; tests/gl/test_uniform_layout.cpp checks it with the driver.
// Library-internal.
#pragma once

#include "gl/block_layout.h"
#include "ocean/foam/gpu/foam_noise_block.h"
#include "swell/gpu/ocean.h"

#include <glm/vec2.hpp>

#include <cstddef>

namespace swell::spectral {

// One sinusoid of a cascade's warp (spectral_warp.h):
// w += amplitude_m * sin(wavevector_radpm . x + phase).
struct alignas(16) WarpWaveUniform {
    glm::vec2 wavevector_radpm;
    glm::vec2 amplitude_m;
    float phaseAtCentre_rad; // at the grid centre, reduced modulo 2*pi in double on the CPU
};

struct alignas(16) CascadeUniform {
    glm::vec2 originTexels;     // the grid centre modulo the patch, texels
    float texelsPerMetre;       // N / L
    float shortestWavelength_m; // the shortest wave the cascade holds (what the LOD weight tests), m
    float vertexWarpCell_m;     // grid cells up to this (m) take the warp interpolated from their vertices
    WarpWaveUniform warp[SWELL_FFT_WARP_WAVES];
};

// One foam level's window (world_foam.h).
struct alignas(16) FoamLevelUniform {
    glm::vec2 centreTexels; // the grid centre in texels modulo the window (as the texture repeats)
    float texelsPerMetre;
    float unused; // (padding)
};

struct alignas(16) SpectralUniforms {
    CascadeUniform cascades[SWELL_FFT_CASCADES];
    glm::vec2 windDirection;       // unit, x,z: foam is drawn out into streaks along it
    float foamStreak;              // how far foam streaks are drawn out along the wind, 1 = not at all
    float unresolvedSlopeVariance; // mean square slope of the waves shorter than the last cascade's
    FoamLevelUniform foamLevels[SWELL_FOAM_LEVELS];
    detail::FoamNoiseUniform foamNoise[SWELL_FOAM_NOISE_MAPS]; // the octaves, coarsest first, then the warp
    float breakingFoamAmount; // foam above this amount was made by a crest breaking now (kBreakingFoamAge_s)
};

inline const gl::BlockStruct& blockStructOf(const WarpWaveUniform*)
{
    using S = WarpWaveUniform;
    static const gl::BlockStruct s{"SpectralWarpWave", "swell::spectral::WarpWaveUniform", sizeof(S),
                                   {SWELL_BLOCK_MEMBER(S, wavevector_radpm), SWELL_BLOCK_MEMBER(S, amplitude_m),
                                    SWELL_BLOCK_MEMBER(S, phaseAtCentre_rad)}};
    return s;
}

inline const gl::BlockStruct& blockStructOf(const CascadeUniform*)
{
    using S = CascadeUniform;
    static const gl::BlockStruct s{"SpectralCascade", "swell::spectral::CascadeUniform", sizeof(S),
                                   {SWELL_BLOCK_MEMBER(S, originTexels), SWELL_BLOCK_MEMBER(S, texelsPerMetre),
                                    SWELL_BLOCK_MEMBER(S, shortestWavelength_m),
                                    SWELL_BLOCK_MEMBER(S, vertexWarpCell_m), SWELL_BLOCK_MEMBER(S, warp)}};
    return s;
}

inline const gl::BlockStruct& blockStructOf(const FoamLevelUniform*)
{
    using S = FoamLevelUniform;
    static const gl::BlockStruct s{"SpectralFoamLevel", "swell::spectral::FoamLevelUniform", sizeof(S),
                                   {SWELL_BLOCK_MEMBER(S, centreTexels), SWELL_BLOCK_MEMBER(S, texelsPerMetre),
                                    SWELL_BLOCK_PADDING(S, unused)}};
    return s;
}

inline const gl::BlockStruct& blockStructOf(const SpectralUniforms*)
{
    using S = SpectralUniforms;
    static const gl::BlockStruct s{"SpectralCascades", "swell::spectral::SpectralUniforms", sizeof(S),
                                   {SWELL_BLOCK_MEMBER(S, cascades), SWELL_BLOCK_MEMBER(S, windDirection),
                                    SWELL_BLOCK_MEMBER(S, foamStreak), SWELL_BLOCK_MEMBER(S, unresolvedSlopeVariance),
                                    SWELL_BLOCK_MEMBER(S, foamLevels), SWELL_BLOCK_MEMBER(S, foamNoise),
                                    SWELL_BLOCK_MEMBER(S, breakingFoamAmount)}};
    return s;
}

} // namespace swell::spectral
