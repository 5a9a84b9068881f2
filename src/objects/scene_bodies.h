// The floating rigid bodies of a scene (SceneObject::isRigidBody()), one
// swell::FloatingBody each, built from the objects' closed shapes and kept
// stepping by the renderer, which asks for their poses once a frame.
#pragma once

#include "assets/mesh_data.h"
#include "swell/floating_body.h"
#include "swell/scene.h"

#include <glm/mat4x4.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace swell::detail {

// The surface bodies float on: the one the water grid draws next to the
// camera (the filter of its finest cells at scale 1), without the horizon
// fade. From the scene's settings alone, so a body's motion does not depend
// on where a viewer's camera wanders.
SurfaceFilter bodySurfaceFilter(const Scene& scene);

// Whether two scenes' objects would move alike: the same rigid bodies, placed
// and built the same way (paths and hull nodes are compared with the assets).
bool sameBodies(const Scene& a, const Scene& b);

class SceneBodies {
public:
    SceneBodies() = default;
    // shapes[i]: object i's closed shape in model space (its hull volume,
    // else its mesh); read only for rigid bodies. `surface` must outlive
    // this. Throws swell::InputError at the object's path key (or naming
    // the object) when a body cannot be built.
    SceneBodies(const Scene& scene, const std::vector<const MeshData*>& shapes, const WaveModel& surface);

    bool empty() const { return count_ == 0; }
    std::size_t count() const { return count_; }
    // Steps every body to time_s together (see FloatingBody::advanceToStep).
    void advanceTo(double time_s);
    // Object i's transform from model space (scale included) to the world at
    // time_s, stepping its body there; nothing when it is not a rigid body.
    std::optional<glm::dmat4> poseAt(std::size_t i, double time_s);
    // Integration steps taken by all bodies so far.
    std::int64_t stepsTaken() const;

private:
    std::vector<std::unique_ptr<FloatingBody>> bodies_; // null for objects that are not bodies
    std::vector<double> scale_;
    std::size_t count_ = 0;
};

} // namespace swell::detail
