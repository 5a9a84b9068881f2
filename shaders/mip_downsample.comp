// Levels source + 1 .. source + SWELL_DOWNSAMPLE_LEVELS of a square 2D array
// texture's mip chain from level `source`, each texel the mean of the 2 x 2
// below it (the box filter glGenerateMipmap applies to power-of-two levels).
// One dispatch writes up to five levels: each workgroup reduces a 32 x 32
// block of the source in shared memory, so a 256^2 chain takes two
// dispatches instead of a draw or blit per level and layer, which measured
// 0.18 to 0.36 ms a chain on an NVIDIA H200 (docs/design/performance-log.md).
#include "swell/gpu/bindings.h"

#define SIDE (1 << (SWELL_DOWNSAMPLE_LEVELS - 1))
layout(local_size_x = SIDE, local_size_y = SIDE) in;

layout(binding = SWELL_UNIT_DOWNSAMPLE_SOURCE) uniform sampler2DArray sourceTexture;
// The levels written, source + 1 .. source + levels; the unused ones unbound.
layout(binding = 0) writeonly uniform image2DArray level1;
layout(binding = 1) writeonly uniform image2DArray level2;
layout(binding = 2) writeonly uniform image2DArray level3;
layout(binding = 3) writeonly uniform image2DArray level4;
layout(binding = 4) writeonly uniform image2DArray level5;
uniform int sourceLevel;
uniform int levels; // 1 .. SWELL_DOWNSAMPLE_LEVELS

shared vec4 block[SIDE][SIDE];

void store(int k, ivec3 p, vec4 v)
{
    if (k == 1)
        imageStore(level1, p, v);
    else if (k == 2)
        imageStore(level2, p, v);
    else if (k == 3)
        imageStore(level3, p, v);
    else if (k == 4)
        imageStore(level4, p, v);
    else
        imageStore(level5, p, v);
}

void main()
{
    const ivec2 local = ivec2(gl_LocalInvocationID.xy);
    const int layer = int(gl_WorkGroupID.z);
    const int size1 = max(textureSize(sourceTexture, sourceLevel).x >> 1, 1);
    // Level source + 1: this invocation's texel, from the four below it.
    const ivec2 p = ivec2(gl_WorkGroupID.xy) * SIDE + local;
    const bool inside = all(lessThan(p, ivec2(size1)));
    vec4 v = vec4(0.0);
    if (inside) {
        const ivec2 q = 2 * p;
        v = 0.25 * ((texelFetch(sourceTexture, ivec3(q, layer), sourceLevel) +
                     texelFetch(sourceTexture, ivec3(q + ivec2(1, 0), layer), sourceLevel)) +
                    (texelFetch(sourceTexture, ivec3(q + ivec2(0, 1), layer), sourceLevel) +
                     texelFetch(sourceTexture, ivec3(q + ivec2(1, 1), layer), sourceLevel)));
        store(1, ivec3(p, layer), v);
    }
    block[local.y][local.x] = v;
    // Each further level from the last one's texels in shared memory: the
    // invocations of the block's top-left quarter, then of its sixteenth...
    for (int k = 2; k <= levels; ++k) {
        barrier();
        const int side = SIDE >> (k - 1);
        const int sizeK = max(size1 >> (k - 1), 1);
        const bool reducing = all(lessThan(local, ivec2(side)));
        if (reducing) {
            const ivec2 q = 2 * local;
            v = 0.25 * ((block[q.y][q.x] + block[q.y][q.x + 1]) + (block[q.y + 1][q.x] + block[q.y + 1][q.x + 1]));
        }
        barrier();
        if (reducing) {
            block[local.y][local.x] = v;
            const ivec2 pk = ivec2(gl_WorkGroupID.xy) * side + local;
            if (all(lessThan(pk, ivec2(sizeK))))
                store(k, ivec3(pk, layer), v);
        }
    }
}
