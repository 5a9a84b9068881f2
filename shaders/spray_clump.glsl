// The spray's clumps and streaks between its passes
// (src/render/spray_passes.cpp): spray_clumps.comp evaluates every slot's
// clump into sprayClumps, in the slots' order; spray_list.comp lists the
// living ones, in that order, in sprayList (a stable partition: the living
// first, then the rest) and writes the commands of the passes after it;
// spray_streaks.comp evaluates each living clump's streaks into
// sprayStreaks, a clump's one after another; spray.vert draws them. Built
// with SWELL_BOW_SPRAY, the bow's clumps (a hull's launch beside the
// crest's).
#ifndef SWELL_SPRAY_CLUMP_GLSL
#define SWELL_SPRAY_CLUMP_GLSL

#include "swell/gpu/bindings.h"
#include "swell/gpu/spray.h"

#ifdef SWELL_BOW_SPRAY
#define SPRAY_DROPS SWELL_BOW_SPRAY_DROPS
#define SPRAY_STRIPS (SWELL_BOW_SPRAY_DROPS + 1) // the piece of sheet, then the drops
#else
#define SPRAY_DROPS SWELL_SPRAY_DROPS
#define SPRAY_STRIPS SWELL_SPRAY_DROPS
#endif

struct SprayClump {
    vec4 birthAge;    // xyz: where the clump left the crest, relative to the render origin, m; w: its age, s
    vec4 windOpacity; // x, y: the wind's direction (x, z), unit; z: its speed at 10 m, m/s; w: opacity, 0: not drawn
    uvec4 key;        // x: its life's hash (its drops' sizes); y, z, w: 0
#ifdef SWELL_BOW_SPRAY
    vec4 bow;     // x, y: the sheet's outward direction (x, z), unit; z: the hull's speed, m/s; w: the plunge, m/s
    vec4 forward; // x, y: the hull's heading of travel (x, z), unit; z: its flare's cotangent; w: 0
#endif
};

// A streak as its vertices draw it: the four points of its path, tail to
// head, each lit (spray_streaks.comp's sprayColor), and the ribbon's
// make.
struct SprayStreak {
    vec4 points[4]; // xyz: the point, relative to the render origin, m; w: 0
    vec4 colors[4]; // rgb: its colour, lit and fogged, in the pass's output encoding; w: 0
    vec4 path;      // xyz: the path tail to head, before any drawing out, m; w: the half width drawn, m
    vec4 look;      // x: opacity; y: 1 drawn, 0 not; z, w: the bow's piece of sheet (spray.frag's vSheet)
};

layout(std430, binding = SWELL_STORAGE_SPRAY_CLUMPS) buffer SprayClumps {
    SprayClump sprayClumps[];
};
layout(std430, binding = SWELL_STORAGE_SPRAY_LIST) buffer SprayList {
    uint sprayList[];
};
// glDrawArraysIndirect's command for the streaks' strips, then
// glDispatchComputeIndirect's for spray_streaks.comp, and the living
// clumps' count.
layout(std430, binding = SWELL_STORAGE_SPRAY_COMMANDS) buffer SprayCommands {
    uint drawCount;
    uint drawInstances;
    uint drawFirst;
    uint drawBaseInstance;
    uint streakGroups[3];
    uint living;
} sprayCommands;
layout(std430, binding = SWELL_STORAGE_SPRAY_STREAKS) buffer SprayStreaks {
    SprayStreak sprayStreaks[];
};

#endif
