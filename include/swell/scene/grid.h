// CPU side of the camera-following LOD grid: where grid lines fall, how the
// grid centre snaps to the camera, and the per-level snap offsets the vertex
// shader uses (shaders/grid.glsl holds the diagram and the GPU twin).
#pragma once

#include "swell/export.h"

#include "swell/gpu/limits.h"
#include "swell/scene/scene.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>

namespace swell {

struct SWELL_API GridShape {
    GridLayout layout = GridLayout::Geometric;
    int cells = 254;          // cells per side, even, >= 4
    double radius_m = 2000.0; // reach of the detailed grid, m (at every scale)
    double skirt_m = 1.0e5;   // where the outermost lines go, m (beyond the fog: unbounded water)
    // Geometric layout: concentric square rings (see GridRings); at scale 1
    // the spacing is about even within innerScale_m of the centre.
    double innerScale_m = 0.0;
    double maxScale = 1.0; // largest height scale: its inner scale stays well inside the reach
};

// Geometric layout, one height scale: ring r of n/2 lies at Chebyshev radius
// f(u) = innerScale * (exp(growth * u) - 1), u = r / (n/2), so spacing is
// about even within innerScale of the centre and grows in proportion to
// distance beyond it; growth makes f(1) = radius at every scale, so a change
// of scale moves the far rings little (by 2^(1 - u) per doubling).
struct SWELL_API GridRings {
    double innerScale_m = 0.0; // scale * shape.innerScale_m
    double growth = 0.0;       // ln(1 + radius / innerScale)
    // The first ring that snaps to each lattice level. A table, so the CPU
    // and the GPU choose a vertex's level alike.
    std::array<int, SWELL_GRID_LEVELS> levelFirstRing{};
};
SWELL_API GridRings gridRings(const GridShape& shape, double scale);

// The grid a scene's settings ask for: cells even, the skirt beyond the fog.
SWELL_API GridShape gridShapeFor(const GridSettings& grid, const CameraSettings& camera);

// Fade distances the renderer uses: the scene's, kept inside the detailed grid.
struct SWELL_API HorizonFade {
    double start_m = 0.0, end_m = 0.0;
};
SWELL_API HorizonFade horizonFadeFor(const GridSettings& grid, const GridShape& shape);

// CPU twin of horizonFade() in the shaders: the factor wave heights are
// scaled by at distance_m from the camera (1 near, 0 beyond end).
SWELL_API double horizonFadeAt(const HorizonFade& fade, double distance_m);

// Offset of grid line i (0..cells) from the centre at scale 1, before
// snapping: the paper's line, or the geometric layout's ring radius f.
SWELL_API double gridLineOffset(const GridShape& shape, int i);

// The finest lattice step at scale 1, m: the innermost cell's spacing for the
// paper's layout, half of it for the geometric one (whose vertices do not lie
// on straight lines, so they snap to a lattice finer than their spacing).
SWELL_API double finestGridStep(const GridShape& shape);

// The geometric grid's scale for a camera this high above the water: 1/4,
// 1/2, 1, 2, ... up to shape.maxScale (a power of two, so every scale's
// lattices are lattices of scale 1), doubling every eightfold of height and
// so keeping triangles a similar size on screen from any height (grid.cpp
// has the heights). Always 1 for the paper's layout. morph (0..1) says how far the grid has slid toward the
// next coarser scale (2 * scale): it rises from 0 to 1 over a band of heights
// below the one where that scale takes over, so that crossing into it moves
// no vertex (geomorphing, as CDLOD morphs its levels: Strugar 2009,
// "Continuous distance-dependent level of detail for rendering heightmaps").
struct SWELL_API GridScale {
    double scale = 1.0;
    double morph = 0.0;
};
SWELL_API GridScale gridScaleFor(const GridShape& shape, double cameraHeight_m);

// Where the grid sits this frame: its scale, its centre snapped to the finest
// step, and the centre modulo each level's step (so the GPU can snap in small
// numbers); and the same for the next coarser scale, which the vertices
// slide toward by `morph`.
struct SWELL_API GridPlacement {
    double scale = 1.0;
    double morph = 0.0;       // 0: the grid of `scale`; 1: that of 2 * scale
    glm::dvec2 center_m{0.0}; // absolute world x,z
    double finestStep_m = 0.0; // scale * finestGridStep(shape)
    std::array<glm::dvec2, SWELL_GRID_LEVELS> snapOffsets{};
    // The coarser scale's centre (snapped to its own finest step, as
    // placeGrid() places that scale), relative to center_m, and its snap
    // offsets: its level l snaps to this scale's level l + 1 lattice.
    glm::dvec2 coarseCenterShift_m{0.0};
    std::array<glm::dvec2, SWELL_GRID_LEVELS> coarseSnapOffsets{};
    GridRings rings, coarseRings; // geometric layout: this scale's rings and the coarser one's
};
SWELL_API GridPlacement placeGrid(const GridShape& shape, glm::dvec3 camera_m);

// CPU twin of gridVertex() in grid.glsl: where grid vertex (i, j) sits.
struct SWELL_API GridPoint {
    glm::dvec2 offset_m{0.0};      // rest position relative to the grid centre after snapping, m
    // The same before snapping (within half a lattice step of offset_m): it
    // does not depend on where the centre snapped, m.
    glm::dvec2 nominal_m{0.0};
    double cellSize_m = 0.0;       // the coarser spacing there, m (drives the wave filter)
    glm::dvec2 latticeStep_m{0.0}; // the world-fixed lattice step it snapped to, per axis, m; 0 on the skirt
                                   // (while morphing: the coarser scale's, the larger)
    // How near the snap was to a tie, in lattice steps (0.5: far from it).
    // Below about 1e-4 the GPU's float arithmetic may pick the other
    // neighbouring lattice point.
    double snapMargin = 0.5;
    bool skirt = false;            // on the outermost ring, out beyond the fog
};
SWELL_API GridPoint gridPoint(const GridShape& shape, const GridPlacement& placement, int i, int j);

} // namespace swell
