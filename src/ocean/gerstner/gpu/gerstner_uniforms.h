// The Gerstner model's std140 uniform block (GerstnerWaves, read by
// shaders/ocean/gerstner.glsl): the C++ struct and its description
// (gl/block_layout.h), from which gpu/gerstner_block.glsl is generated at
// build time; tests/gl/test_uniform_layout.cpp checks it with the driver.
#pragma once

#include "gl/block_layout.h"
#include "swell/gpu/limits.h"

#include <glm/vec2.hpp>

#include <cstddef>

namespace swell::detail {

// One wave, its phase referenced to the grid centre for the view.
struct alignas(16) GerstnerWaveUniform {
    glm::vec2 direction;        // of travel, unit (x, z)
    float wavenumber_rad_per_m; // k
    float amplitude_m;
    float steepness;            // Q
    float phase_rad;            // at the grid centre and this time
    float wavelength_m;
    // Mean square slope of this wave and every shorter one: what a pixel
    // that resolves none of them adds as roughness.
    float tailSlopeVariance;
    // Its layer of the coast field's texture array (swell/coast_field.h,
    // ocean/coast/gpu/coast_gpu.h), -1: none.
    int coastLayer;
};

// The waves sorted longest first.
struct alignas(16) GerstnerUniforms {
    GerstnerWaveUniform waves[SWELL_MAX_WAVES];
    int waveCount; // waves in use
};

inline const gl::BlockStruct& blockStructOf(const GerstnerWaveUniform*)
{
    using S = GerstnerWaveUniform;
    static const gl::BlockStruct s{"GerstnerWave", "swell::detail::GerstnerWaveUniform", sizeof(S),
                                   {SWELL_BLOCK_MEMBER(S, direction), SWELL_BLOCK_MEMBER(S, wavenumber_rad_per_m),
                                    SWELL_BLOCK_MEMBER(S, amplitude_m), SWELL_BLOCK_MEMBER(S, steepness),
                                    SWELL_BLOCK_MEMBER(S, phase_rad), SWELL_BLOCK_MEMBER(S, wavelength_m),
                                    SWELL_BLOCK_MEMBER(S, tailSlopeVariance), SWELL_BLOCK_MEMBER(S, coastLayer)}};
    return s;
}

inline const gl::BlockStruct& blockStructOf(const GerstnerUniforms*)
{
    using S = GerstnerUniforms;
    static const gl::BlockStruct s{"GerstnerWaves", "swell::detail::GerstnerUniforms", sizeof(S),
                                   {SWELL_BLOCK_MEMBER_AS(S, waves, "gerstnerWaves"),
                                    SWELL_BLOCK_MEMBER_AS(S, waveCount, "gerstnerWaveCount")}};
    return s;
}

} // namespace swell::detail
