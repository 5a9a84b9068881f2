// A perspective camera in world space, in double precision; the renderer
// draws relative to its x,z so precision does not depend on where it is.
#pragma once

#include "swell/export.h"

#include "swell/scene/scene.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace swell {

struct SWELL_API Camera {
    glm::dvec3 position_m{0.0, 6.0, 0.0}; // world position, m
    double yaw_deg = 0.0;                  // heading, degrees from -z towards +x
    double pitch_deg = 0.0;                // degrees, -89..89
    double fovY_deg = 60.0;                // vertical field of view, degrees
    double near_m = 0.1, far_m = 20000.0;  // clip planes, m
    // About the view direction, degrees, -180..180: + banks the camera to
    // the right (its up turns towards its right), so the horizon in the
    // image turns counter-clockwise. A camera on a rolling deck. (Last, so
    // that aggregate initialisers written before it still compile.)
    double roll_deg = 0.0;

    glm::dvec3 forward() const;
    // View matrix for positions relative to `origin_m` (the render origin).
    glm::dmat4 viewRelativeTo(glm::dvec3 origin_m) const;
    glm::dmat4 projection(double aspect) const;
};

// The scene's camera at time t: its fixed pose, or its path interpolated.
// (A mounted camera's pose is relative to its object: Renderer::sceneCameraAt.)
SWELL_API Camera cameraAt(const CameraSettings& settings, double time_s);

// A camera carried by an object: `relative` stands at its position_m in the
// object's axes and looks with its yaw, pitch and roll turned from them;
// `objectToWorld` places the object (a rigid transform, or one with a
// uniform scale, which does not scale the offset). The result in the world.
SWELL_API Camera mountedCamera(const Camera& relative, const glm::dmat4& objectToWorld);

} // namespace swell
