// The coast field's std140 uniform block (Coast, read by
// shaders/coast_field.glsl): where the field's samples lie for the view,
// and the trains a wave model hands the field in place of its own longest
// waves (the spectral model's; the Gerstner model's waves carry their own
// layers). The C++ struct and its description (gl/block_layout.h), from
// which gpu/coast_block.glsl is generated at build time;
// tests/gl/test_uniform_layout.cpp checks it with the driver.
#pragma once

#include "gl/block_layout.h"
#include "swell/coast_field.h"

#include <glm/vec2.hpp>

namespace swell::detail {

// One train, its phase referenced to the grid centre for the view, as a
// Gerstner wave's (gerstner_uniforms.h).
struct alignas(16) CoastTrainUniform {
    glm::vec2 direction;        // of travel in the open sea, unit (x, z)
    float wavenumber_rad_per_m; // k in the open sea
    float amplitude_m;          // in the open sea
    float steepness;            // Q
    float phase_rad;            // at the grid centre and this time
    float wavelength_m;         // in the open sea (the LOD filter's)
    int layer;                  // of the field's texture array
};

struct alignas(16) CoastUniforms {
    CoastTrainUniform trains[kMaxCoastWaves]; // longest first
    int trainCount;
    // The field's layers (0: no field), its sample (0, 0) relative to the
    // grid centre, its samples along x and z and their spacing.
    int layers;
    glm::vec2 origin_m;
    glm::ivec2 size;
    float cell_m;
    // The trains' share of the longest band (swell::CoastTrainShare): whole
    // at depths up to fullDepth_m, none from noneDepth_m, m.
    float trainsFullDepth_m;
    float trainsNoneDepth_m;
    float edgeBand_cells; // the field's blend into the open sea at its edges, samples
};

inline const gl::BlockStruct& blockStructOf(const CoastTrainUniform*)
{
    using S = CoastTrainUniform;
    static const gl::BlockStruct s{"CoastTrain", "swell::detail::CoastTrainUniform", sizeof(S),
                                   {SWELL_BLOCK_MEMBER(S, direction), SWELL_BLOCK_MEMBER(S, wavenumber_rad_per_m),
                                    SWELL_BLOCK_MEMBER(S, amplitude_m), SWELL_BLOCK_MEMBER(S, steepness),
                                    SWELL_BLOCK_MEMBER(S, phase_rad), SWELL_BLOCK_MEMBER(S, wavelength_m),
                                    SWELL_BLOCK_MEMBER(S, layer)}};
    return s;
}

inline const gl::BlockStruct& blockStructOf(const CoastUniforms*)
{
    using S = CoastUniforms;
    static const gl::BlockStruct s{"Coast", "swell::detail::CoastUniforms", sizeof(S),
                                   {SWELL_BLOCK_MEMBER_AS(S, trains, "coastTrains"),
                                    SWELL_BLOCK_MEMBER_AS(S, trainCount, "coastTrainCount"),
                                    SWELL_BLOCK_MEMBER_AS(S, layers, "coastLayers"),
                                    SWELL_BLOCK_MEMBER_AS(S, origin_m, "coastOrigin_m"),
                                    SWELL_BLOCK_MEMBER_AS(S, size, "coastSize"),
                                    SWELL_BLOCK_MEMBER_AS(S, cell_m, "coastCell_m"),
                                    SWELL_BLOCK_MEMBER_AS(S, trainsFullDepth_m, "coastTrainsFullDepth_m"),
                                    SWELL_BLOCK_MEMBER_AS(S, trainsNoneDepth_m, "coastTrainsNoneDepth_m"),
                                    SWELL_BLOCK_MEMBER_AS(S, edgeBand_cells, "coastEdgeBand_cells")}};
    return s;
}

} // namespace swell::detail
