// The fleet's design numbers (swell::kFleetObjects): what
// assets/models/fleet_model.py put in each model's root `extras`, read from
// the copy compiled into the library, so the scene's checks, the models'
// stretching and the bodies' design loading share the script's numbers.
#pragma once

#include <glm/vec3.hpp>

#include <string_view>

namespace swell::detail {

struct FleetDesign {
    double length_m = 0.0;        // the hull volume's overall length
    double beam_m = 0.0;          // its greatest breadth
    double draft_m = 0.0;         // its lowest point below the design waterline (y = 0)
    double displacement_kg = 0.0; // sea water it displaces below that waterline
    glm::dvec3 centerOfMass_m{0.0}; // above the centre of buoyancy: it floats level there at that mass
};

// The design of the fleet model `name` ("tug", without "builtin:"); throws
// swell::Error for a name outside kFleetObjects.
const FleetDesign& fleetDesign(std::string_view name);

// Its glTF text as the script wrote it (assets/models/fleet/NAME.gltf).
std::string_view fleetModelText(std::string_view name);

// The bounds a scene may stretch a model to, as fractions of its design
// length and beam: past them its superstructure and rig no longer look
// like the type's, and a narrow hull with a high centre of mass capsizes.
inline constexpr double kFleetLengthRange[2] = {0.5, 2.0};
inline constexpr double kFleetBeamRange[2] = {0.75, 1.5};

} // namespace swell::detail
