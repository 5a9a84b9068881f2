// The paper's camera-following LOD grid, generated from the vertex index.
//
// Grid line i of n (i = 0..n) sits at offset s(i) from the grid centre:
//
//     u    = (i - n/2) / (n/2)             in -1..1
//     s(i) = radius * u * |u|               the paper's p = 1/2 + (2/n^2)|i - n/2|(i - n/2), scaled
//
//     -R                 0                 +R
//     |    |   |  | | ||||||| | |  |   |    |     spacing grows linearly with distance
//
// Lines 0 and n are moved out to a skirt far beyond the fog, so the water has
// no edge. To keep the surface from swimming as the camera moves, the centre
// snaps to the finest step and each line snaps to a world-fixed lattice whose
// step is the largest power-of-two multiple of the finest step not above the
// line's own spacing: a vertex only ever sits on world-fixed points of its level.
#ifndef SWELL_GRID_GLSL
#define SWELL_GRID_GLSL
#include "frame.glsl"

float gridLineOffset(float i)
{
    float half_n = 0.5 * gridShape.y;
    float u = (i - half_n) / half_n;
    return gridShape.x * u * abs(u);
}

// Offset of line i after snapping to its level's lattice; spacing returns the
// line's spacing (the smaller gap to its neighbours), m.
float snappedLine(int i, int axis, out float spacing)
{
    float n = gridShape.y;
    float s = gridLineOffset(float(i));
    if (i == 0 || i == int(n)) {
        spacing = gridShape.z;
        return sign(s) * gridShape.z;
    }
    spacing = min(gridLineOffset(float(i + 1)) - s, s - gridLineOffset(float(i - 1)));
    float step0 = gridShape.w;
    int level = clamp(int(floor(log2(max(spacing, step0) / step0))), 0, SWELL_GRID_LEVELS - 1);
    float step = step0 * exp2(float(level));
    float offset = snapOffsets[level][axis];
    return step * floor((offset + s) / step + 0.5) - offset;
}

struct GridVertex {
    vec2 offset;     // rest position relative to the grid centre, m
    float cellSize;  // the coarser of the two spacings there, m
};

GridVertex gridVertex(int vertexId)
{
    int lines = int(gridShape.y) + 1;
    int i = vertexId % lines;
    int j = vertexId / lines;
    float sx, sz;
    vec2 offset = vec2(snappedLine(i, 0, sx), snappedLine(j, 1, sz));
    return GridVertex(offset, max(sx, sz));
}

// Wave height fades to 0 between gridFade.x and gridFade.y metres (Earth curvature).
float horizonFade(float distance_m)
{
    return 1.0 - smoothstep(gridFade.x, gridFade.y, distance_m);
}
#endif
