// The sea's mean square slope, for the reflection's masking term: how often
// a reflected ray that leaves the water at a low angle meets another wave.
#pragma once

#include "swell/surface_query.h"

namespace swell::detail {

// The mean of |grad eta|^2 (the squared tangent of the normal's tilt, both
// directions together) over the surface at time 0: 4096 rest points of a
// 2 km square, at fixed quasi-random places (the R2 sequence), so the same
// model always gives the same value. Flat water gives 0.
double meanSquareSlope(const SurfaceQuery& model);

} // namespace swell::detail
