// Spray from the bows of hulls under way (objects/bow_spray.h), the first
// pass of its spray, built with SWELL_BOW_SPRAY (spray_clumps.comp is the
// crests'): SWELL_BOW_SPRAY_SLOTS slots a hull, their lives the crest
// spray's, born on the bow's waterline from the stem aft, either side,
// where the bow was at its birth, and drawn as the hull's share at that
// birth says (its speed through the water and the bow's plunging into the
// waves, sampled on the CPU from the bodies' steps and handed over as a
// short history). It reads no wave model: its wind is the scene's.
#ifndef SWELL_BOW_SPRAY
#error "bow_spray_clumps.comp is built with SWELL_BOW_SPRAY (render/shader_programs.h)"
#endif
#include "swell/gpu/spray.h"
#include "frame.glsl"
#include "spray.glsl"
#include "spray_clumps_pass.glsl"

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
