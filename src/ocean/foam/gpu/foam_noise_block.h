// One lattice of the whitecaps' foam texture (swell::foam::FoamNoiseMap)
// as the uniform blocks hold it: the spectral model's (anchored at its grid
// centre) and the surface sources' (anchored at the render origin). One C++
// struct and its description (gl/block_layout.h); GLSL's FoamNoise is
// generated from it into gpu/foam_noise.glsl, which shaders/whitecap_foam.glsl
// includes.
#pragma once

#include "gl/block_layout.h"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <cstddef>

namespace swell::detail {

// Cells q = map * x + offset_cells for x from the lattices' origin, m.
struct alignas(16) FoamNoiseUniform {
    glm::vec4 map{0.0f};          // column-major 2 x 2: cells per metre along x, then along z
    glm::vec2 offset_cells{0.0f}; // the origin's cell modulo SWELL_FOAM_NOISE_PERIOD
    float cyclesPerMetre = 0.0f;  // across the streaks: what the footprint filters
};

inline const gl::BlockStruct& blockStructOf(const FoamNoiseUniform*)
{
    using S = FoamNoiseUniform;
    static const gl::BlockStruct s{"FoamNoise", "swell::detail::FoamNoiseUniform", sizeof(S),
                                   {SWELL_BLOCK_MEMBER(S, map), SWELL_BLOCK_MEMBER(S, offset_cells),
                                    SWELL_BLOCK_MEMBER(S, cyclesPerMetre)},
                                   "gpu/foam_noise.glsl", "src/ocean/foam/gpu/foam_noise_block.h"};
    return s;
}

} // namespace swell::detail
