// The spectral ocean's whitecap foam, kept in the world rather than in the
// periodic cascades (whose foam repeated with their patches, a grid seen
// from high up): SWELL_FOAM_LEVELS windows of SWELL_FOAM_SIZE^2 texels that
// follow the grid centre, each stored toroidally (world texel w at w mod N)
// so that a moving camera rewrites only the texels entering along the
// window's edges. shaders/ocean/spectral_foam.comp makes and ages the foam,
// worldFoam() in shaders/ocean/spectral.glsl reads it.
#pragma once

#include "ocean/spectral/spectral_cpu.h"
#include "ocean/spectral/spectral_field.h"
#include "swell/gpu/ocean.h"

#include <glm/vec2.hpp>

#include <vector>

namespace swell::spectral {

inline constexpr int kFoamSize = SWELL_FOAM_SIZE;
inline constexpr int kFoamLevels = SWELL_FOAM_LEVELS;

// Foam needs the history of the breaking: a frame that follows the last by
// more than kLongestFoamStep_s, or goes back in time, first replays the
// foam's history on the steps foamReplayOffsets_s() gives, so a still at any
// time shows the foam a sequence arriving there would (the same for every
// still at that time). An interactive renderer (the viewer) never replays
// on a frame later than the last: it takes one step, however long.
inline constexpr double kLongestFoamStep_s = 1.0;
// The replay steps every kFoamReplayStep_s over kFoamReplayLifetimes
// lifetimes: the lattice a sequence of frames takes, so the replayed foam is
// the sequence's but for what its first frame carried in. Its steps grow
// with the lifetime (20 at 3.85 s, 300 at 60 s): sparser steps before the
// last 10 s (36 in all at 60 s) were tried and missed too many breakings
// (the foam cover of a 60 s-lifetime still fell from 0.44 to 0.27). What
// keeps a still cheap is the cost of a step instead: on a software
// rasteriser, FoamReplay (foam_replay.h) takes the steps before the last on
// the CPU at about an eighteenth of the GPU shaders' cost there.
inline constexpr double kFoamReplayStep_s = 0.5;
inline constexpr double kFoamReplayLifetimes = 2.5;

// A still's replay at this foam lifetime: how long before the frame each
// step is, s, the oldest first, the last 0 (the frame itself), each a whole
// number of kFoamReplayStep_s.
std::vector<double> foamReplayOffsets_s(double lifetime_s);

// A level's texel, m: level 0's are those of the finest cascade that folds
// into foam (kFoamCascades), so the foam is as sharp as the folds it marks;
// each further level's are SWELL_FOAM_LEVEL_RATIO times wider.
double foamTexel_m(const SpectralField& field, int level);

// Where a level's window lies for a grid centre.
struct FoamWindow {
    // World texel (x, z) holding the grid centre, modulo 2^32: the shader
    // only takes differences of indices, which wrap correctly.
    glm::ivec2 centreIndex{0};
    glm::vec2 centreFraction{0.0f}; // the grid centre within that texel, 0..1
    glm::ivec2 origin{0};           // the window's first texel: centreIndex - N/2
    glm::vec2 originTexels{0.0f};   // the grid centre in texels modulo N, for the lookup
};
FoamWindow foamWindowAt(glm::dvec2 gridCenter_m, double texel_m);

} // namespace swell::spectral
