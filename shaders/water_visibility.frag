// The water's visibility pass: each pixel keeps which of the grid's
// triangles it shows (1 + its index in the grid's index buffer, 0 where
// no water is), so that the shading pass (water.frag with
// SWELL_WATER_DEFERRED) shades each water pixel once however small the
// triangles are (render/water_visibility.h). The depth test against the
// world and itself leaves the nearest.
#include "frame.glsl"

// The first triangle of this draw in the grid's index buffer (the tiles
// are drawn a range at a time, and gl_PrimitiveID counts from each draw's
// first).
uniform uint firstTriangle;

out uint triangleId;

void main()
{
    triangleId = firstTriangle + uint(gl_PrimitiveID) + 1u;
}
