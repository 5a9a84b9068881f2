// CPU side of the paper's LOD grid: where grid lines fall, how the grid
// centre snaps to the camera, and the per-level snap offsets the vertex
// shader uses (shaders/grid.glsl holds the diagram and the GPU twin).
#pragma once

#include "swell/scene.h"
#include "swell/shader_constants.h"

#include <glm/vec2.hpp>

#include <array>

namespace swell {

struct GridShape {
    int cells = 256;          // cells per side, even, >= 4
    double radius_m = 2000.0; // half-size of the detailed grid, m
    double skirt_m = 1.0e5;   // where the outermost lines go, m (beyond the fog: unbounded water)
};

// The grid a scene's settings ask for: cells even, the skirt beyond the fog.
GridShape gridShapeFor(const GridSettings& grid, const CameraSettings& camera);

// Fade distances the renderer uses: the scene's, kept inside the detailed grid.
struct HorizonFade {
    double start_m = 0.0, end_m = 0.0;
};
HorizonFade horizonFadeFor(const GridSettings& grid, const GridShape& shape);

// CPU twins of horizonFade() and waveLodWeight() in the shaders: the factor
// wave heights are scaled by at distance_m from the camera (1 near, 0 beyond
// end), and the weight of a wave of wavelength_m on cells cellSize_m wide.
double horizonFadeAt(const HorizonFade& fade, double distance_m);
double waveLodWeight(double wavelength_m, double cellSize_m);

// Offset of grid line i (0..cells) from the centre before snapping: radius * u * |u|.
double gridLineOffset(const GridShape& shape, int i);

// Spacing of the innermost cell, m: the step the grid centre snaps to.
double finestGridStep(const GridShape& shape);

// Where the grid sits this frame: its centre snapped to the finest step, and
// the centre modulo each level's step (so the GPU can snap in small numbers).
struct GridPlacement {
    glm::dvec2 center_m{0.0};  // absolute world x,z
    double finestStep_m = 0.0;
    std::array<glm::dvec2, SWELL_GRID_LEVELS> snapOffsets{};
};
GridPlacement placeGrid(const GridShape& shape, glm::dvec2 camera_m);

// CPU twin of snappedLine() in grid.glsl: offset of line i from the centre
// along axis (0: x, 1: z) after snapping; spacing receives the line's spacing.
double snappedGridLine(const GridShape& shape, const GridPlacement& placement, int i, int axis, double& spacing_m);

} // namespace swell
