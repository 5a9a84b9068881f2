// Spray and spume torn from the breaking crests (issue 25), first pass:
// one invocation per clump of drops, each a pure function of its slot and the simulated time
// (spray.glsl, twinned in src/render/spray_kinematics.h), so a still at any
// time shows what a sequence of frames arriving there would, bit for bit.
// The clumps live in the slots of a square lattice of cells anchored to the
// world (a cell keeps its clumps while the eye moves); each slot is born
// again every SWELL_SPRAY_LIFETIME_S at a phase of its own, at a place a
// counter-based hash of (cell, slot, life) picks in its cell, and lives
// only where the whitecaps' foam says a crest broke there lately. Its
// record (spray_clump.glsl) says where and when it left the crest, or that
// it is not drawn; spray_list.comp lists the living ones and spray.vert
// flies their drops apart, drawing each as a streak of its path.
//
// Spume: drops of 20 to 500 um torn from the crest tops by winds from about
// 10 m/s up, launched near the crest and taken up by the wind within a
// fraction of a second (Andreas 1998, J. Phys. Oceanogr. 28, "A new sea
// spray generation function for wind speeds up to 32 m/s"; Veron 2015,
// Annu. Rev. Fluid Mech. 47, "Ocean spray", secs. 2 and 4).
//
// The clumps find the crests through the wave model's GLSL (its whitecap
// foam, worldFoam(), and the displacement of its cascades): a model whose
// crests break says so (WaveModelGpu::crestSpray). The bows' spray is
// bow_spray_clumps.comp.
#include "swell/gpu/ocean.h"
#include "swell/gpu/spray.h"
#include "frame.glsl"
#include "ocean.glsl"
#include "spray.glsl"
#include "spray_clumps_pass.glsl"

// The wind's direction is the model's: windDirection (ocean/spectral.glsl).
void clump(int index)
{
    vOpacity = 0.0;
    vBirth = vec3(0.0);
    vWind = vec3(0.0);
    vAge_s = 0.0;
    vKey = 0u;
    int slot = index % SWELL_SPRAY_SLOTS;
    int cellIndex = index / SWELL_SPRAY_SLOTS;
    ivec2 cell = ivec2(cellIndex % SWELL_SPRAY_CELLS, cellIndex / SWELL_SPRAY_CELLS);
    SprayLife life = sprayLife(sprayFirstCell + cell, slot, sprayTime_s);
    if (sprayUnit(life.key, 1u) >= sprayAmount)
        return; // before the foam's lookup: most slots stop here in a near gale
    vec2 rest = sprayCornerFromGrid_m + (vec2(cell) + life.inCell) * float(SWELL_SPRAY_CELL_M);
    if (!sprayLives(life.key, worldFoam(rest, 0.5, false), breakingFoamAmount, sprayAmount))
        return;
    vec3 surface = vec3(0.0);
    for (int c = 0; c < SWELL_FFT_CASCADES; ++c) {
        mat2 jacobian;
        surface += bilinearDisplacement(warpedTexels(c, rest, jacobian), c).xyz;
    }
    vec2 place = (vec2(cell) + life.inCell) * float(SWELL_SPRAY_CELL_M);
    vBirth = vec3(sprayCorner_m.x + place.x, 0.0, sprayCorner_m.y + place.y) + surface;
    vWind = vec3(windDirection, sprayWindSpeed_mps);
    vAge_s = life.age_s;
    vKey = life.key;
    float lifetime_s = float(SWELL_SPRAY_LIFETIME_S);
    vOpacity = smoothstep(0.0, 0.05, life.age_s) * (1.0 - smoothstep(0.5 * lifetime_s, lifetime_s, life.age_s));
}
