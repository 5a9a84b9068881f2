// The spray's second pass (src/render/spray_passes.cpp): the living clumps
// of spray_clumps.comp's records, listed in the slots' order (a stable
// partition of the slots: the living first, then the rest, so every entry
// is written), and the commands of the passes after it: the dispatch of
// their streaks (spray_streaks.comp) and the draw of them (spray.vert).
// One workgroup: each invocation counts the living in its run of slots,
// the first sums the runs in turn, and each lists its run from its sum.
// Nothing depends on which invocation finishes first, so the draw's order,
// and with it the blended frame, is the same in every run.
#include "swell/gpu/bindings.h"
#include "swell/gpu/spray.h"
#include "spray_clump.glsl"

layout(local_size_x = SWELL_SPRAY_LIST_GROUP) in;

uniform int sprayListSlots; // the slots spray_clumps.comp wrote

shared uint runStart[SWELL_SPRAY_LIST_GROUP];
shared uint livingAll;

bool lives(uint slot) { return sprayClumps[slot].windOpacity.w > 0.0; }

void main()
{
    uint run = gl_LocalInvocationID.x;
    uint slots = uint(sprayListSlots);
    uint per = (slots + uint(SWELL_SPRAY_LIST_GROUP) - 1u) / uint(SWELL_SPRAY_LIST_GROUP);
    uint begin = min(run * per, slots), end = min(begin + per, slots);
    uint count = 0u;
    for (uint slot = begin; slot < end; ++slot)
        count += lives(slot) ? 1u : 0u;
    runStart[run] = count;
    barrier();
    if (run == 0u) {
        uint sum = 0u;
        for (uint r = 0u; r < uint(SWELL_SPRAY_LIST_GROUP); ++r) {
            uint n = runStart[r];
            runStart[r] = sum;
            sum += n;
        }
        livingAll = sum;
        uint streaks = sum * uint(SPRAY_STRIPS);
        sprayCommands.drawCount = streaks * uint(SWELL_SPRAY_STRIP_VERTICES);
        sprayCommands.drawInstances = 1u;
        sprayCommands.drawFirst = 0u;
        sprayCommands.drawBaseInstance = 0u;
        sprayCommands.streakGroups[0] = (streaks + uint(SWELL_SPRAY_GROUP) - 1u) / uint(SWELL_SPRAY_GROUP);
        sprayCommands.streakGroups[1] = 1u;
        sprayCommands.streakGroups[2] = 1u;
        sprayCommands.living = sum;
    }
    barrier();
    // The dead after all the living, in the slots' order too.
    uint live = runStart[run], dead = livingAll + begin - runStart[run];
    for (uint slot = begin; slot < end; ++slot) {
        if (lives(slot))
            sprayList[live++] = slot;
        else
            sprayList[dead++] = slot;
    }
}
