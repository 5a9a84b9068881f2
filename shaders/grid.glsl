// The camera-following LOD grid, generated from the vertex index.
//
// Grid line i of n (i = 0..n) sits at offset s(i) from the grid centre, with
// u = (i - n/2) / (n/2) in -1..1. Two layouts (the variant SWELL_GRID_LAYOUT):
//
// paper (SWELL_GRID_PAPER): the paper's quadratic division points, p = 1/2 + (2/n^2)|i - n/2|(i - n/2), scaled:
//
//     s(i) = radius * u * |u|                    spacing grows with sqrt(distance)
//
//     -R                 0                 +R
//     |    |   |  | | ||||||| | |  |   |    |
//
// Its lines run the whole grid, so the fine lines near the centre make slivers
// far out. geometric (SWELL_GRID_GEOMETRIC, the default) uses concentric square rings instead:
// ring r = max(|i - n/2|, |j - n/2|) lies at Chebyshev radius
//
//     f(r) = a * (exp(k * r / (n/2)) - 1),   a = scale * r0,   k = ln(1 + radius / a)
//
// with its vertices evenly along each side (vertex (i, j) at (i - n/2, j - n/2) * f(r) / r):
//
//     +-------------------------------+     spacing about even within r0 of
//     |   +-----------------------+   |     the centre, then in proportion to
//     |   |    +-------------+    |   |     distance both across and along
//     |   |    |  +-------+  |    |   |     the rings: no slivers, and a
//     |   |    |  |  +-+  |  |    |   |     grazing view's far triangles keep
//     |   |    |  |  +-+  |  |    |   |     their size on screen
//     |   |    |  +-------+  |    |   |
//     |   |    +-------------+    |   |
//     |   +-----------------------+   |
//     +-------------------------------+
//
// The inner scale a doubles (scale ..., 1/2, 1, 2, ...) with each eightfold
// of the camera's height, so the water below a high camera is not
// over-tessellated nor the far water seen from low down, while the reach
// stays `radius`: ring u moves by 2^(1 - u) per doubling, the far rings
// hardly at all. Over a band of heights below each switch the vertices slide
// (gridMorph 0..1) toward where the next coarser scale puts them, so the
// switch moves nothing (geomorphing; grid.cpp has the heights):
//
//     height m    5.9       13.2                                 47
//     scale       |-- 1 ------------------------------------------|-- 2 --...
//     gridMorph    0  0  0  0 .1 .2 .3 .4 .5 .6 .7 .8 .9  1      | 0  0 ...
//
// The outermost lines (ring) are moved out to a skirt far beyond the fog, so
// the water has no edge. To keep the surface from swimming as the camera
// moves, the centre snaps to the finest step, and each vertex snaps to a
// world-fixed lattice whose step is a power-of-two multiple of the finest
// step: not above the line's spacing (paper), or half the ring's spacing
// (geometric; its level comes from a per-ring table, gridLevels[l].firstRing, so
// the CPU twin agrees). A vertex only ever sits on world-fixed points of its
// level. The finest step of scale 2^m is 2^m times that of scale 1, so every
// scale's lattices are lattices of scale 1.
#ifndef SWELL_GRID_GLSL
#define SWELL_GRID_GLSL
#include "swell/gpu/limits.h"
#include "swell/gpu/variants.h"
#include "frame.glsl"

struct GridVertex {
    vec2 offset;     // rest position relative to the grid centre, m
    float cellSize;  // the coarser of the two spacings there, m
};

float snapToLattice(float s, float step, float offset)
{
    return step * floor((offset + s) / step + 0.5) - offset;
}

// The paper's layout: offset of line i (scale is 1).
float paperLineOffset(float i)
{
    float half_n = 0.5 * gridCells;
    float u = (i - half_n) / half_n;
    return gridRadius_m * u * abs(u);
}

// Offset of line i after snapping to its level's lattice; spacing returns the
// line's spacing (the smaller gap to its neighbours), m.
float paperLine(int i, int axis, out float spacing)
{
    float n = gridCells;
    if (i == 0 || i == int(n)) {
        spacing = gridSkirt_m;
        return (i == 0 ? -1.0 : 1.0) * gridSkirt_m;
    }
    float s = paperLineOffset(float(i));
    spacing = min(paperLineOffset(float(i + 1)) - s, s - paperLineOffset(float(i - 1)));
    float step0 = gridFinestStep_m;
    int level = clamp(int(floor(log2(max(spacing, step0) / step0))), 0, SWELL_GRID_LEVELS - 1);
    return snapToLattice(s, step0 * exp2(float(level)), gridLevels[level].snapOffset_m[axis]);
}

// Vertex d of ring `ring` at this frame's grid scale (coarse false), or at
// the next coarser one (twice the scale, its own centre and snap offsets).
GridVertex geometricVertexAt(ivec2 d, int ring, int half_n, bool coarse)
{
    float r0 = coarse ? 2.0 * gridInnerScale_m : gridInnerScale_m, k = coarse ? gridCoarseGrowth : gridGrowth;
    float u = float(ring) / float(half_n);
    float radius = r0 * (exp(k * u) - 1.0);
    float radial = r0 * k * exp(k * u) / float(half_n);
    float tangential = ring == 0 ? radial : radius / float(ring);
    int level = 0;
    for (int l = 1; l < SWELL_GRID_LEVELS; ++l)
        level = ring >= int(coarse ? gridLevels[l].coarseFirstRing : gridLevels[l].firstRing) ? l : level;
    // Level l of the coarser scale snaps to this scale's level l + 1 lattice.
    float step = gridFinestStep_m * exp2(float(coarse ? level + 1 : level));
    vec2 snapOffset = coarse ? gridLevels[level].coarseSnapOffset_m : gridLevels[level].snapOffset_m;
    vec2 nominal = vec2(d) * tangential;
    vec2 offset = vec2(snapToLattice(nominal.x, step, snapOffset.x), snapToLattice(nominal.y, step, snapOffset.y));
    return GridVertex(coarse ? offset + gridCoarseCenterShift : offset, max(radial, tangential));
}

GridVertex geometricVertex(int i, int j)
{
    int half_n = int(gridCells) / 2;
    ivec2 d = ivec2(i, j) - half_n;
    int ring = max(abs(d.x), abs(d.y));
    if (ring == half_n)
        return GridVertex(vec2(d) * (gridSkirt_m / float(half_n)), gridSkirt_m);
    GridVertex fine = geometricVertexAt(d, ring, half_n, false);
    if (gridMorph <= 0.0)
        return fine;
    // Geomorphing (Strugar 2009): slide toward the coarser scale's vertex, so
    // that the switch to that scale at gridMorph = 1 moves nothing.
    GridVertex coarse = geometricVertexAt(d, ring, half_n, true);
    return GridVertex(mix(fine.offset, coarse.offset, gridMorph), mix(fine.cellSize, coarse.cellSize, gridMorph));
}

GridVertex gridVertex(int vertexId)
{
    int lines = int(gridCells) + 1;
    int i = vertexId % lines;
    int j = vertexId / lines;
#if SWELL_GRID_LAYOUT == SWELL_GRID_GEOMETRIC
    return geometricVertex(i, j);
#else
    float sx, sz;
    vec2 offset = vec2(paperLine(i, 0, sx), paperLine(j, 1, sz));
    return GridVertex(offset, max(sx, sz));
#endif
}

// The cell (i, j) whose rest square holds rest offset r (from the grid
// centre), before the waves move it: where a search for the drawn triangle
// over a point starts. A guess (the morph's coarser centre is left out):
// the search looks in rings around it. The CPU twin is
// swell::detail::restCellOf (src/core/drawn_search.h).
ivec2 gridCellOf(vec2 r)
{
    int half_n = int(gridCells) / 2;
#if SWELL_GRID_LAYOUT == SWELL_GRID_GEOMETRIC
    float chebyshev = max(abs(r.x), abs(r.y));
    if (chebyshev <= 0.0)
        return ivec2(half_n);
    float fine = float(half_n) * log(1.0 + chebyshev / gridInnerScale_m) / gridGrowth;
    float coarse = float(half_n) * log(1.0 + chebyshev / (2.0 * gridInnerScale_m)) / gridCoarseGrowth;
    vec2 line = r * (mix(fine, coarse, gridMorph) / chebyshev);
#else
    // s = R u |u|  =>  u = sign(s) sqrt(|s| / R).
    vec2 line = sign(r) * sqrt(abs(r) / gridRadius_m) * float(half_n);
#endif
    return clamp(ivec2(floor(line)) + half_n, ivec2(0), ivec2(int(gridCells) - 1));
}

// Wave height fades to 0 between gridFadeStart_m and gridFadeEnd_m metres (Earth curvature).
float horizonFade(float distance_m)
{
    return 1.0 - smoothstep(gridFadeStart_m, gridFadeEnd_m, distance_m);
}
#endif
