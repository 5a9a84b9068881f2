// The water's shading pass's geometry: a square point over each screen
// tile that shows water (listed by water_tiles.comp). A point is one
// primitive: two triangles a tile would split the rasteriser's blocks
// along their diagonal and shade those blocks twice (1.5 shading runs a
// pixel at 8 x 8 tiles, measured). Its sides lie on pixel corners, so each
// pixel of a tile is drawn once.
#include "swell/gpu/bindings.h"
#include "frame.glsl"

layout(std430, binding = SWELL_STORAGE_WATER_TILES) readonly buffer WaterTiles {
    uint command[4];
    uint tiles[];
};

void main()
{
    uint tile = tiles[gl_VertexID];
    vec2 centre = (vec2(tile & 0xffffu, tile >> 16) + 0.5) * float(SWELL_WATER_TILE);
    // The pass's viewport widened to whole tiles (render/water_pass.cpp):
    // a point whose centre lies outside the viewport is not drawn.
    vec2 tiled = ceil(round(1.0 / viewportInvSize) / float(SWELL_WATER_TILE)) * float(SWELL_WATER_TILE);
    gl_Position = vec4(centre / tiled * 2.0 - 1.0, 0.0, 1.0);
    gl_PointSize = float(SWELL_WATER_TILE);
}
