// The spray's first pass, shared by the crests' (spray_clumps.comp) and the
// bows' (bow_spray_clumps.comp): its uniforms, the clump's record in its
// parts, and the pass's main(), which writes each slot's record from what
// the including file's clump() made of it.
#ifndef SWELL_SPRAY_CLUMPS_PASS_GLSL
#define SWELL_SPRAY_CLUMPS_PASS_GLSL
#include "swell/gpu/bindings.h"
#include "spray_clump.glsl"

layout(local_size_x = SWELL_SPRAY_GROUP) in;

uniform vec2 sprayTime_s;      // x: the time within a period of 4096 lifetimes, s; y: the period's index
uniform ivec2 sprayFirstCell;  // the world index (x, z) of the lattice's first cell
uniform vec2 sprayCorner_m;    // that cell's corner, relative to the render origin, m
uniform vec2 sprayCornerFromGrid_m; // ... relative to the grid centre (the rest offsets' origin), m
uniform float sprayWindSpeed_mps; // the wind's speed at 10 m, m/s
uniform float sprayAmount;     // the share of the slots that may live, 0..1

// The clump's record (spray_clump.glsl), in its parts.
vec3 vBirth;      // where the clump left the crest, relative to the render origin, m
vec3 vWind;       // x, y: the wind's direction (x, z), unit; z: its speed at 10 m, m/s
float vAge_s;     // since it left
uint vKey;        // its life's hash: its drops' sizes
float vOpacity;   // 0: not drawn
#ifdef SWELL_BOW_SPRAY
vec4 vBow;      // x, y: the sheet's outward direction (x, z), unit; z: the hull's speed, m/s; w: the plunge, m/s
vec3 vForward;  // x, y: the hull's heading of travel (x, z), unit; z: its flare's cotangent
#endif

// Fills the record's parts for slot `index` (the including file's).
void clump(int index);

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
#endif
