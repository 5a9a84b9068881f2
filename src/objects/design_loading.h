// How one of the fleet is loaded to float at its design draft
// (docs/BODIES.md, "The fleet"): weighing the water its hull displaces below
// the design waterline, with its centre of mass on one vertical with that
// water's centroid, at the design's height.
#pragma once

#include "swell/floating_body.h"

#include <glm/vec3.hpp>

namespace swell::detail {

struct DesignLoading {
    double mass_kg = 0.0;
    glm::dvec3 centerOfMassOffset_m{0.0}; // from the shape's centroid, as BodySettings takes it
};

// The volume of a closed shape below the plane y = level_m, m^3, and its
// centroid: each triangle clipped to its part below the plane, summed as
// signed tetrahedra with an apex on the plane, so the waterplane that
// closes the cut adds nothing (the divergence theorem; Blow & Binstock
// 2004 for the tetrahedra).
struct VolumeBelow {
    double volume_m3 = 0.0;
    glm::dvec3 centroid_m{0.0};
};
VolumeBelow volumeBelow(const BodyShape& shape, double level_m);

// The loading that floats `shape` (model frame, scaled as it is placed)
// level with its model origin on calm water: Archimedes' principle, the
// weight the displaced water's and the centre of mass above the centre of
// buoyancy (Journee & Massie 2001, Offshore Hydromechanics, sec. 2.1).
// centerOfMassHeight_m: the centre of mass's height above the waterline.
DesignLoading designLoadingOf(const BodyShape& shape, double centerOfMassHeight_m, double waterDensity_kg_per_m3);

} // namespace swell::detail
