// Lists the screen tiles (SWELL_WATER_TILE pixels a side) in which the
// water's visibility pass left a triangle, into the indirect draw of the
// water's shading pass (water_tiles.vert), so that the shading runs on the
// water's pixels and not the sky's (render/water_visibility.h).
#include "swell/gpu/bindings.h"

layout(local_size_x = SWELL_WATER_TILE, local_size_y = SWELL_WATER_TILE) in;

layout(binding = SWELL_UNIT_WATER_VISIBILITY) uniform usampler2D waterVisibility;

// glDrawArraysIndirect's command (its vertex count is the tiles': a point
// each), then each tile's x and y, 16 bits each.
layout(std430, binding = SWELL_STORAGE_WATER_TILES) buffer WaterTiles {
    uint tileCount;
    uint instanceCount;
    uint firstVertex;
    uint baseInstance;
    uint tiles[];
};

shared bool showsWater;

void main()
{
    if (gl_LocalInvocationIndex == 0u)
        showsWater = false;
    barrier();
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (all(lessThan(texel, textureSize(waterVisibility, 0))) && texelFetch(waterVisibility, texel, 0).r != 0u)
        showsWater = true;
    barrier();
    if (gl_LocalInvocationIndex == 0u && showsWater)
        tiles[atomicAdd(tileCount, 1u)] = gl_WorkGroupID.x | (gl_WorkGroupID.y << 16);
}
