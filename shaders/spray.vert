// Spray and spume torn from the breaking crests (issue 25): one vertex per
// particle, each a pure function of its index and the simulated time, so a
// still at any time shows what a sequence of frames arriving there would,
// bit for bit. The particles live in the slots of a square lattice of cells
// anchored to the world (a cell keeps its particles while the eye moves);
// each slot is born again every SWELL_SPRAY_LIFETIME_S at a phase of its own,
// at a place a counter-based hash of (cell, slot, life) picks in its cell,
// and lives only where the whitecaps' foam says a crest breaks there now
// (worldFoam under two to four seconds old). Each
// particle is a clump of drops torn off together; the geometry shader
// (spray.geom) flies its drops of three sizes apart and draws each as a
// soft puff drawn out along its velocity.
//
// The drops' flight (spume: drops of 20 to 500 um torn from the crest tops
// by winds from about 10 m/s up, launched near the crest and taken up by
// the wind within a fraction of a second; Andreas 1998, J. Phys. Oceanogr.
// 28, "A new sea spray generation function for wind speeds up to 32 m/s";
// Veron 2015, Annu. Rev. Fluid Mech. 47, "Ocean spray", secs. 2 and 4):
// flown in closed form (spray.geom). The
// launch (up 1 to 4 m/s, downwind 0.3 to 0.6 of the wind) and the wind the
// drops meet over the crests (0.8 of the wind at 10 m) are chosen by eye.
#include "frame.glsl"
#include "ocean.glsl"
#include "spray.glsl"

uniform vec2 sprayTime_s;      // x: the time within a period of 4096 lifetimes, s; y: the period's index
uniform ivec2 sprayFirstCell;  // the world index (x, z) of the lattice's first cell
uniform vec2 sprayCorner_m;    // that cell's corner, relative to the render origin, m
uniform vec2 sprayCornerFromGrid_m; // ... relative to the grid centre (the rest offsets' origin), m
uniform float sprayWindSpeed_mps; // the wind's speed at 10 m, m/s (its direction: windDirection, spectral.glsl)
uniform float sprayAmount;     // the share of the slots that may live, 0..1

out vec3 vBirth;      // where the clump left the crest, relative to the render origin, m
out vec3 vLaunch;     // its launch velocity, m/s
out vec3 vWind;       // the wind over the crests, m/s (x, z)
out float vAge_s;     // since it left
out flat uint vKey;   // its life's hash: its drops' sizes
out float vOpacity;   // 0: not drawn

void main()
{
    vOpacity = 0.0;
    vBirth = vec3(0.0);
    vLaunch = vec3(0.0);
    vWind = vec3(0.0);
    vAge_s = 0.0;
    vKey = 0u;
    gl_Position = vec4(0.0);
    int slot = gl_VertexID % SWELL_SPRAY_SLOTS;
    int cellIndex = gl_VertexID / SWELL_SPRAY_SLOTS;
    ivec2 cell = ivec2(cellIndex % SWELL_SPRAY_CELLS, cellIndex / SWELL_SPRAY_CELLS);
    ivec2 worldCell = sprayFirstCell + cell;
    uint slotKey = sprayHash(uint(worldCell.x) * 0x9e3779b1u ^ sprayHash(uint(worldCell.y) ^ sprayHash(uint(slot))));
    // The slot's lives: each starts at a phase of the slot's own.
    float lifetime_s = float(SWELL_SPRAY_LIFETIME_S);
    float local_s = sprayTime_s.x + sprayUnit(slotKey, 0u) * lifetime_s;
    float life = floor(local_s / lifetime_s);
    float age_s = local_s - life * lifetime_s;
    uint lifeIndex = uint(int(sprayTime_s.y)) * 4096u + uint(int(life));
    uint key = sprayHash(slotKey ^ sprayHash(lifeIndex));
    if (sprayUnit(key, 1u) >= sprayAmount)
        return;
    // The birth place, and whether a crest broke there lately: certainly
    // where its foam is under two seconds old (above breakingFoamAmount^2 =
    // exp(-2 s / lifetime): the spray's life and a little more), not where
    // it is four seconds old, in between the likelier the younger.
    vec2 inCell = vec2(sprayUnit(key, 2u), sprayUnit(key, 3u));
    vec2 rest = sprayCornerFromGrid_m + (vec2(cell) + inCell) * float(SWELL_SPRAY_CELL_M);
    float foam = worldFoam(rest, 0.5, false);
    float young = breakingFoamAmount * breakingFoamAmount, old = young * young;
    float breaking = clamp((foam - old) / max(young - old, 1e-3), 0.0, 1.0);
    if (sprayUnit(key, 4u) >= breaking)
        return;
    vec3 surface = vec3(0.0);
    for (int c = 0; c < SWELL_FFT_CASCADES; ++c) {
        mat2 jacobian;
        surface += bilinearDisplacement(warpedTexels(c, rest, jacobian), c).xyz;
    }
    vec2 place = (vec2(cell) + inCell) * float(SWELL_SPRAY_CELL_M);
    vBirth = vec3(sprayCorner_m.x + place.x, 0.0, sprayCorner_m.y + place.y) + surface;
    vec2 wind_mps = windDirection * sprayWindSpeed_mps;
    vec2 across = vec2(-windDirection.y, windDirection.x);
    vLaunch = vec3(0.0, 1.0 + 3.0 * sprayUnit(key, 6u), 0.0);
    vLaunch.xz = wind_mps * (0.3 + 0.3 * sprayUnit(key, 7u)) + across * (sprayUnit(key, 8u) - 0.5) * 2.0;
    vWind = vec3(0.8 * wind_mps.x, 0.0, 0.8 * wind_mps.y);
    vAge_s = age_s;
    vKey = key;
    vOpacity = smoothstep(0.0, 0.08, age_s) * (1.0 - smoothstep(0.5 * lifetime_s, lifetime_s, age_s));
    gl_Position = vec4(vBirth, 1.0);
}
