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
// Built with SWELL_BOW_SPRAY, the same pass throws spray from the bows of
// the hulls under way instead (objects/bow_spray.h): SWELL_BOW_SPRAY_SLOTS
// slots a hull, their lives the crest spray's, born on the bow's waterline
// from the stem aft, either side, where the bow was at its birth, and drawn
// as the hull's share at that birth says (its speed through the water and
// the bow's plunging into the waves, sampled on the CPU from the bodies'
// steps and handed over as a short history).
#include "swell/gpu/bindings.h"
#include "swell/gpu/ocean.h"
#include "swell/gpu/spray.h"
#include "frame.glsl"
#ifndef SWELL_BOW_SPRAY
#include "ocean.glsl"
#endif
#include "spray.glsl"
#include "spray_clump.glsl"

layout(local_size_x = SWELL_SPRAY_GROUP) in;

uniform vec2 sprayTime_s;      // x: the time within a period of 4096 lifetimes, s; y: the period's index
uniform ivec2 sprayFirstCell;  // the world index (x, z) of the lattice's first cell
uniform vec2 sprayCorner_m;    // that cell's corner, relative to the render origin, m
uniform vec2 sprayCornerFromGrid_m; // ... relative to the grid centre (the rest offsets' origin), m
uniform float sprayWindSpeed_mps; // the wind's speed at 10 m, m/s (its direction: windDirection, spectral.glsl)
uniform float sprayAmount;     // the share of the slots that may live, 0..1

// The clump's record (spray_clump.glsl), in its parts.
vec3 vBirth;      // where the clump left the crest, relative to the render origin, m
vec3 vWind;       // x, y: the wind's direction (x, z), unit; z: its speed at 10 m, m/s
float vAge_s;     // since it left
uint vKey;        // its life's hash: its drops' sizes
float vOpacity;   // 0: not drawn

#ifdef SWELL_BOW_SPRAY
uniform int bowHulls;                               // hulls drawn, up to SWELL_BOW_SPRAY_HULLS
uniform int bowBody[SWELL_BOW_SPRAY_HULLS];         // each one's object index: its lives' key
// x, y: its velocity over the ground (x, z), m/s; z, w: its heading of travel, unit (x, z).
uniform vec4 bowMotion[SWELL_BOW_SPRAY_HULLS];
// x, y: the unit (x, z) towards the first side's stations, out from the keel; z: its speed, m/s;
// w: the cotangent of its bow's flare (BowLine::flareCot).
uniform vec4 bowAcross[SWELL_BOW_SPRAY_HULLS];
// Where the sheet leaves the bow now (objects/bow_spray.h's BowLine),
// relative to the render origin (x, z), m: per hull the first side's
// stations, then the other's, each from the stem aft.
uniform vec2 bowStations[SWELL_BOW_SPRAY_HULLS * 2 * SWELL_BOW_SPRAY_STATIONS];
// The hull's history, newest first (bowSpraySample): x: the share of the
// slots born, y: the bow's plunge into the water, m/s, z: the height the
// sheet leaves the bow at, m (sea frame: relative to the render origin).
uniform vec4 bowHistory[SWELL_BOW_SPRAY_HULLS * SWELL_BOW_SPRAY_HISTORY];
uniform float bowHistoryLag_s;                      // the newest sample's age, s
uniform vec2 bowWindDirection;                      // the wind's, unit (x, z): any wave model's
vec4 vBow;      // x, y: the sheet's outward direction (x, z), unit; z: the hull's speed, m/s; w: the plunge, m/s
vec3 vForward;  // x, y: the hull's heading of travel (x, z), unit; z: its flare's cotangent

void clump(int index)
{
    vOpacity = 0.0;
    vBirth = vec3(0.0);
    vWind = vec3(0.0);
    vAge_s = 0.0;
    vKey = 0u;
    vBow = vec4(0.0);
    vForward = vec3(0.0);
    int hull = index / SWELL_BOW_SPRAY_SLOTS;
    int slot = index % SWELL_BOW_SPRAY_SLOTS;
    if (hull >= bowHulls)
        return;
    SprayLife life = sprayLife(ivec2(bowBody[hull], SWELL_BOW_SPRAY_CELL_Y), slot, sprayTime_s);
    int then = bowSpraySample(life.age_s, bowHistoryLag_s);
    if (then >= SWELL_BOW_SPRAY_HISTORY)
        return;
    vec4 born = bowHistory[hull * SWELL_BOW_SPRAY_HISTORY + then];
    if (!bowSprayLives(life.key, born.x))
        return;
    // Where on the waterline: crowded towards the stem, which meets the
    // water first and throws the most; even slots on the first side.
    int side = slot & 1;
    float along = life.inCell.x * life.inCell.x * float(SWELL_BOW_SPRAY_STATIONS - 1);
    int k = min(int(along), SWELL_BOW_SPRAY_STATIONS - 2);
    int first = (hull * 2 + side) * SWELL_BOW_SPRAY_STATIONS;
    vec2 station = mix(bowStations[first + k], bowStations[first + k + 1], along - float(k));
    vec4 motion = bowMotion[hull];
    // Outward from the flare, turned forward at the stem (the stem parts
    // the water ahead of it) and abeam at the shoulder.
    vec2 across = bowAcross[hull].xy * (side == 0 ? 1.0 : -1.0);
    float aft = along / float(SWELL_BOW_SPRAY_STATIONS - 1);
    vec2 outward = normalize(across + motion.zw * (0.6 * (1.0 - aft)));
    // Born where that point of the bow was then: the hull is carried at a
    // constant velocity (docs/BODIES.md), at the sheet's height then.
    vec2 place = station - motion.xy * life.age_s;
    vBirth = vec3(place.x, born.z, place.y);
    vWind = vec3(bowWindDirection, sprayWindSpeed_mps);
    vAge_s = life.age_s;
    vKey = life.key;
    vBow = vec4(outward, bowAcross[hull].z, born.y);
    vForward = vec3(motion.zw, bowAcross[hull].w);
    float lifetime_s = float(SWELL_SPRAY_LIFETIME_S);
    vOpacity = smoothstep(0.0, 0.05, life.age_s) * (1.0 - smoothstep(0.5 * lifetime_s, lifetime_s, life.age_s));
}
#else
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
#endif

// One slot a invocation (SWELL_SPRAY_GROUP divides the slots drawn); its
// record, written whether it lives or not.
void main()
{
    int index = int(gl_GlobalInvocationID.x);
    clump(index);
    SprayClump c;
    c.birthAge = vec4(vBirth, vAge_s);
    c.windOpacity = vec4(vWind, vOpacity);
    c.key = uvec4(vKey, 0u, 0u, 0u);
#ifdef SWELL_BOW_SPRAY
    c.bow = vBow;
    c.forward = vec4(vForward, 0.0);
#endif
    sprayClumps[index] = c;
}
