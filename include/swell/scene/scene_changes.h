// What changed between two scenes, in the parameter table's terms
// (swell/scene/parameters.h): the union of the declared effects of every parameter
// whose value differs, plus what the scene's shape asks (objects added or
// removed or given other files, other sky images, another asset folder, the
// wind switched on or off, waves added or removed, seabed shapes added or
// removed or another heightmap). The renderer and the
// viewer decide what a change costs from this alone.
#pragma once

#include "swell/export.h"

#include "swell/scene/parameters.h"

namespace swell {

SWELL_API ParameterEffect sceneChanges(const Scene& before, const Scene& after);

} // namespace swell
