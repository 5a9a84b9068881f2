// Where a scene's objects stand: its floating rigid bodies built on a
// surface and stepped (objects/scene_bodies.h), the objects that ride the
// water without being bodies set on the frame's answers for the water
// under them, and fixed objects where the scene puts them. The renderer
// asks this once per simulated time; every view and pass draws with it.
#pragma once

#include "assets/scene_assets.h"
#include "objects/scene_bodies.h"
#include "ocean/probed_point.h"
#include "swell/scene/scene.h"
#include "swell/surface_query.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include <memory>
#include <optional>
#include <vector>

namespace swell::detail {

// The floating bodies of `scene` on `surface` (the water on the scene's
// clock), built from the scene's shapes, their wake over `seabed`.
SceneBodies buildBodies(const SceneShapes& shapes, const Scene& scene, std::shared_ptr<const SurfaceQuery> surface,
                        std::shared_ptr<const Seabed> seabed);

// Where the frame asks for the water under its floating objects (those that
// ride the waves without being rigid bodies), x, z in the sea frame, m, in
// the scene's object order.
std::vector<glm::dvec2> floatingObjectPoints(const Scene& scene);

// Each object's transform (object to the sea frame, m) at time_s: rigid
// bodies where `bodies` has stepped them to time_s (on the surface their
// own filter gives, from the scene alone: swell/floating_body.h); other
// floating objects sit on the water as drawn (the grid's triangles) at
// their position, and tilt with the exact surface's normal: `water` holds
// the frame's answers for floatingObjectPoints(), in its order.
std::vector<glm::dmat4> objectPoses(const Scene& scene, const std::vector<ProbedPoint>& water, SceneBodies& bodies,
                                    double time_s);

// Each object's motion at time_s (sea frame), once objectPoses() has
// stepped the bodies there: a rigid body's from its state
// (SceneBodies::velocityAt), a fixed object's zero; nothing for an object
// that rides the drawn water without being a rigid body (it has no state:
// the frame's water under it sets its pose).
std::vector<std::optional<FloatingBody::Velocity>> objectVelocities(const Scene& scene, const SceneBodies& bodies,
                                                                    double time_s);

// An object's transform standing at position_m (sea frame), tilted by
// `tilt`, turned by its yaw and scaled: a fixed object's at its own position.
glm::dmat4 placedObjectPose(const SceneObject& o, glm::dvec3 position_m, const glm::dmat4& tilt = glm::dmat4(1.0));

} // namespace swell::detail
