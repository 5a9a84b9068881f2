// A hull with many triangles, simplified for its hydrostatics: the pressure
// sum runs over every triangle at every step (120 a second), so a detailed
// model (a 2,000,000-triangle glTF) cost 3 s of CPU a simulated second.
// Above kMaxHydrostaticTriangles the hull is clustered on a grid (each
// cell's vertices merged at their mean; triangles that collapse dropped,
// and pairs that face each other cancel), which keeps the surface closed
// (a vertex map takes a closed surface to a closed one), then scaled about
// its centroid to the full hull's volume, so that the body floats at the
// same displacement. The triangles' count, not the body's motion, is what
// the simplification changes: tests/cpu/test_hull_simplify.cpp holds the
// error of the simplified hull's buoyancy against the full one's.
#pragma once

#include "swell/floating_body.h"

#include <cstddef>

namespace swell::detail {

// Most triangles a body's hydrostatics sums a step. The built-in boat's
// hull has 1140; the cost is about 1.6 us a triangle-step on the machine
// of docs/PERFORMANCE.md, 6.5 ms a simulated second at the bound.
inline constexpr std::size_t kMaxHydrostaticTriangles = 4096;

// `shape` when it has at most maxTriangles triangles; else the simplified
// hull described above, of at most maxTriangles, enclosing `volume_m3`
// (the full hull's) about `centroid_m`.
BodyShape hydrostaticHull(const BodyShape& shape, double volume_m3, glm::dvec3 centroid_m,
                          std::size_t maxTriangles = kMaxHydrostaticTriangles);

// The volume a closed (possibly self-touching) triangle surface encloses,
// m^3: the divergence theorem's sum over its triangles.
double enclosedVolume(const BodyShape& shape);

} // namespace swell::detail
