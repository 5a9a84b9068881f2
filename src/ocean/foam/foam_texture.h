// The whitecaps' look, which every foam on the water shares (the spectral
// model's breaking crests, and the foam of surface sources such as the
// wake, shaders/whitecap_foam.glsl): its age split, and the lattices of its
// texture (foamLook()): octaves of gradient noise, each on its own lattice
// turned by the golden angle from the last, so that no two share an axis and
// their sum has no cells; one more, coarser, warps the first. Each lattice
// is anchored to the world: its cells are q = map * x + offset for x
// relative to the grid centre, with the offset reduced modulo the noise's
// period (SWELL_FOAM_NOISE_PERIOD cells) in double here, so the texture
// stays where it is on the water however the grid centre moves and however
// far it is from the origin.
#pragma once

#include "swell/gpu/ocean.h"

#include <glm/mat2x2.hpp>
#include <glm/vec2.hpp>

#include <array>

namespace swell::foam {

inline constexpr int kFoamOctaves = SWELL_FOAM_OCTAVES;
inline constexpr int kFoamNoiseMaps = SWELL_FOAM_NOISE_MAPS;

// Foam younger than this is the breaking's own: the crest folding now and
// the second after it (a spilling breaker's active phase lasts about a
// wave period's fraction, a second or two at the wavelengths of the
// spectral model's foam cascades), drawn dense and bright over the older
// foam thinning into lace.
inline constexpr double kBreakingFoamAge_s = 1.0;

// The share of the water foam of this amount covers (1 where a crest breaks
// now, decaying as exp(-age / lifetime); breakingAmount: the amount a
// second old), over an area or at a point sampled at random: foamLook()'s
// share in shaders/whitecap_foam.glsl, which the texture's threshold keeps
// at every distance.
double foamShare(double amount, double breakingAmount);

// One lattice: cells q = map * x + offset_cells for x in metres from the
// grid centre along (x, z).
struct FoamNoiseMap {
    glm::mat2 map{1.0f};         // cells per metre, turned and streaked
    glm::vec2 offset_cells{0.0f}; // the grid centre's cell, modulo the period
    float cyclesPerMetre = 0.0f;  // across the streaks (the finest direction): what the footprint filters
};

// The octaves' lattices (kFoamOctaves, coarsest first) and the warp's (the
// last) for a grid centre (absolute, m), the wind's unit direction (x, z)
// and how far streaks are drawn out along it (1: not at all).
std::array<FoamNoiseMap, kFoamNoiseMaps> foamNoiseMaps(glm::dvec2 gridCenter_m, glm::dvec2 windDirection,
                                                       double streak);

} // namespace swell::foam
