#include "label_object_json.h"

#include <glm/mat3x3.hpp>

namespace swell::app {

nlohmann::ordered_json velocityJson(const ObjectLabel& o, const CameraCalibration& c)
{
    if (!o.velocityKnown)
        return nullptr;
    // Directions turn with camera_from_world's rotation alone: the velocity
    // is over the ground in both, the camera's own motion not taken off.
    const glm::dmat3 cameraFromWorld(c.cameraFromWorld);
    const glm::dvec3 v = o.velocity_m_per_s, w = o.angularVelocity_rad_per_s;
    const glm::dvec3 cv = cameraFromWorld * v, cw = cameraFromWorld * w;
    return {{"linear_mps", {v.x, v.y, v.z}},
            {"angular_radps", {w.x, w.y, w.z}},
            {"camera_linear_mps", {cv.x, cv.y, cv.z}},
            {"camera_angular_radps", {cw.x, cw.y, cw.z}}};
}

} // namespace swell::app
