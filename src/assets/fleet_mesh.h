// The fleet's models as a scene object asks for them (docs/SCENE.md, "The
// fleet"): the design model compiled in (core/fleet.h), stretched along its
// length and beam with its draft kept, its "hull" and "superstructure"
// paints changed, its "superstructure" node left out.
#pragma once

#include "assets/mesh_data.h"
#include "swell/scene/scene.h"

#include <glm/vec3.hpp>

#include <string>
#include <string_view>

namespace swell::detail {

struct FleetLook {
    double lengthScale = 1.0; // model x
    double beamScale = 1.0;   // model z
    glm::dvec3 hullColor{-1.0};           // linear RGB; negative: the model's own
    glm::dvec3 superstructureColor{-1.0};
    bool superstructure = true;

    bool operator==(const FleetLook&) const = default;
};

// The look an object of the fleet asks for (its path must be one of it).
FleetLook fleetLookOf(const SceneObject& object);

// What tells two looks apart, for sharing one model between objects.
std::string fleetLookKey(const FleetLook& look);

// The fleet model `name` ("tug") drawn and its hull volume, in that look.
GltfModel makeFleetModel(std::string_view name, const FleetLook& look = {});

} // namespace swell::detail
