// How a point finds the drawn triangle under it (swell::DrawnSurface): the
// search itself, apart from where the grid's vertices come from, so the
// frame's queries answered on the GPU (render/surface_probe.h) search their
// read-back vertices exactly as DrawnSurface searches its own.
// Library-internal.
#pragma once

#include "swell/drawn_surface.h"
#include "swell/scene/grid.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <functional>
#include <optional>

namespace swell::detail {

// Rings of cells searched round the first guess: the drawn surface's
// vertices move sideways by up to the model's horizontal reach, which near
// the camera can span several of its small cells.
inline constexpr int kMaxDrawnSearchRings = 16;

// The cell (i, j) whose rest-space square holds rest offset r (from the grid
// centre), before the waves move it: where the search starts. The GLSL
// twin is gridCellOf() in shaders/grid.glsl.
glm::ivec2 restCellOf(const GridShape& shape, const GridPlacement& placement, glm::dvec2 restOffset_m);

// Grid vertex (i, j) as the vertex shader places it (absolute world
// position, m), or empty when the caller cannot give it (which ends the
// search with nothing).
using DrawnVertexFunction = std::function<std::optional<glm::dvec3>(int i, int j)>;

// The first triangle over world point p (x, z) in rings of cells round
// `start`, up to maxRings: the cells of ring r in the order DrawnSurface
// has always searched them. Empty when none holds it, or when `vertex`
// could not give a vertex the search needed.
std::optional<DrawnPoint> searchDrawnCells(const GridShape& shape, glm::ivec2 start, glm::dvec2 p, int maxRings,
                                           const DrawnVertexFunction& vertex);

} // namespace swell::detail
