// Levels source + 1 .. source + levels of a square 2D array texture's mip
// chain from level `source`, each texel the mean of the 2 x 2 below it: the
// same box filter as shaders/mip_downsample.comp, for a software rasteriser.
// Each invocation reduces its own block of 2^levels x 2^levels source texels
// through every level it writes, in a local array: no shared memory and no
// barriers. llvmpipe emulates a workgroup's barriers (the shared-memory pass
// took about 25 ms a 4-layer 256^2 chain there), and its own mipmap
// generation is a draw per level and layer on the calling thread (about
// 0.5 ms of its CPU a chain): this pass is two dispatches a 256^2 chain,
// and builds a second chain of the same size (chain B: another texture,
// another format) in the same dispatches, its layers after chain A's.
#include "swell/gpu/bindings.h"

layout(local_size_x = SWELL_DOWNSAMPLE_BLOCKS_GROUP, local_size_y = SWELL_DOWNSAMPLE_BLOCKS_GROUP) in;

layout(binding = SWELL_UNIT_DOWNSAMPLE_SOURCE) uniform sampler2DArray sourceA;
layout(binding = SWELL_UNIT_DOWNSAMPLE_SOURCE_B) uniform sampler2DArray sourceB;
// The levels written, source + 1 .. source + levels, of each chain; the
// unused ones unbound.
layout(binding = 0) writeonly uniform image2DArray levelA1;
layout(binding = 1) writeonly uniform image2DArray levelA2;
layout(binding = 2) writeonly uniform image2DArray levelA3;
layout(binding = 3) writeonly uniform image2DArray levelA4;
layout(binding = 4) writeonly uniform image2DArray levelB1;
layout(binding = 5) writeonly uniform image2DArray levelB2;
layout(binding = 6) writeonly uniform image2DArray levelB3;
layout(binding = 7) writeonly uniform image2DArray levelB4;
uniform int sourceLevel;
uniform int levels; // 1 .. SWELL_DOWNSAMPLE_BLOCK_LEVELS
uniform int layersA; // layers from this on are chain B's

// Level source + 1's side in a block of the most levels.
#define SIDE1 (1 << (SWELL_DOWNSAMPLE_BLOCK_LEVELS - 1))

vec4 fetch(bool b, ivec3 p)
{
    return b ? texelFetch(sourceB, p, sourceLevel) : texelFetch(sourceA, p, sourceLevel);
}

void store(bool b, int k, ivec3 p, vec4 v)
{
    if (b) {
        if (k == 1)
            imageStore(levelB1, p, v);
        else if (k == 2)
            imageStore(levelB2, p, v);
        else if (k == 3)
            imageStore(levelB3, p, v);
        else
            imageStore(levelB4, p, v);
    } else {
        if (k == 1)
            imageStore(levelA1, p, v);
        else if (k == 2)
            imageStore(levelA2, p, v);
        else if (k == 3)
            imageStore(levelA3, p, v);
        else
            imageStore(levelA4, p, v);
    }
}

void main()
{
    // Chain B's layers follow chain A's; both are the same size.
    const bool b = int(gl_GlobalInvocationID.z) >= layersA;
    const int layer = int(gl_GlobalInvocationID.z) - (b ? layersA : 0);
    const ivec2 block = ivec2(gl_GlobalInvocationID.xy);
    // The caller asks for no more levels than the source has below it, so
    // level source + 1 holds a whole number of blocks.
    const int side1 = 1 << (levels - 1);
    const int size1 = max(textureSize(sourceA, sourceLevel).x >> 1, 1);
    if (any(greaterThanEqual(block * side1, ivec2(size1))))
        return;
    // Level source + 1 from the source; each later level in place over the
    // one before (row by row, a texel is written after the four it reads,
    // which lie in later rows or, in row 0, in later columns).
    vec4 t[SIDE1 * SIDE1];
    for (int y = 0; y < side1; ++y)
        for (int x = 0; x < side1; ++x) {
            const ivec2 p = block * side1 + ivec2(x, y);
            const ivec2 q = 2 * p;
            const vec4 v = 0.25 * ((fetch(b, ivec3(q, layer)) + fetch(b, ivec3(q + ivec2(1, 0), layer))) +
                                   (fetch(b, ivec3(q + ivec2(0, 1), layer)) + fetch(b, ivec3(q + ivec2(1, 1), layer))));
            store(b, 1, ivec3(p, layer), v);
            t[y * SIDE1 + x] = v;
        }
    for (int k = 2; k <= levels; ++k) {
        const int side = side1 >> (k - 1);
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x) {
                const int top = 2 * y * SIDE1 + 2 * x, bottom = top + SIDE1;
                const vec4 v = 0.25 * ((t[top] + t[top + 1]) + (t[bottom] + t[bottom + 1]));
                t[y * SIDE1 + x] = v;
                store(b, k, ivec3(block * side + ivec2(x, y), layer), v);
            }
    }
}
