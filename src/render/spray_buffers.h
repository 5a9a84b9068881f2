// The buffers between the spray's passes (shaders/spray_clump.glsl,
// render/spray_passes.cpp): spray_clumps.comp's record of every slot's
// clump, spray_list.comp's list of the living ones and the commands of the
// passes after it (which that list writes), spray_streaks.comp's streaks
// of the living clumps, which spray.vert draws. Created at their first
// use, for the slots then drawn or more.
#pragma once

#include "swell/debug.h"
#include "swell/gl/handle.h"
#include "swell/gpu/spray.h"

namespace swell::detail {

// A slot's record (spray_clump.glsl's SprayClump, std430): three vec4 for
// the crests' spray, two more for the bows'.
constexpr long long kSprayClumpBytes = 3 * 16;
constexpr long long kBowSprayClumpBytes = 5 * 16;
// A streak's (SprayStreak): ten vec4.
constexpr long long kSprayStreakBytes = 10 * 16;
// The commands (SprayCommands): glDrawArraysIndirect's (count,
// instanceCount, first, baseInstance), glDispatchComputeIndirect's (three
// group counts) at kSprayDispatchOffset, and the living clumps' count.
constexpr long long kSprayCommandsBytes = 8 * 4;
constexpr long long kSprayDispatchOffset = 4 * 4;

struct SprayBuffers {
    gl::Buffer clumps, list, commands, streaks;
    long long slots = 0;        // the slots they hold
    long long bytesARecord = 0; // a slot's record's
    // Makes them hold `slotsDrawn` records of recordBytes and as many
    // clumps' `strips` streaks (every slot may live), bound to their shader
    // storage bindings, the commands to the indirect draw's and dispatch's
    // bindings.
    void bind(long long slotsDrawn, long long recordBytes, int strips);
};

// What a spray pass writes other than by drawing that the CPU knows of, as
// GpuWork counts it: its three dispatches (the clumps, the list, the
// streaks) and their barriers, every slot's record, the list (every slot:
// the living, then the rest) and the commands. The streaks, as many as the
// GPU found living, are not counted.
GpuWork sprayPassWork(long long slots, long long recordBytes);

} // namespace swell::detail
