#include "label_rig.h"

#include "label_world_frame.h"

#include "swell/constants.h"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>

namespace swell::app {

namespace {

Json vectorJson(glm::dvec3 v) { return {v.x, v.y, v.z}; }

} // namespace

std::vector<std::string> frameCameras(const Scene& scene)
{
    if (scene.camera.rig.empty())
        return {""};
    std::vector<std::string> names;
    for (const RigCamera& c : scene.camera.rig)
        names.push_back(c.name);
    return names;
}

Json platformJson(const PlatformMotion& m, const Camera& platform, LabelWorldFrame frame,
                  const std::optional<PlatformMotion>& previous)
{
    const glm::dmat3 turn = frameFromSwell(frame);
    const glm::dquat orientation = glm::normalize(glm::quat_cast(turn * glm::mat3_cast(m.orientation)));
    const ImuReading imu = imuReadingOf(m);
    Json increment = nullptr;
    if (previous) {
        const ImuIncrement d = imuIncrementOf(*previous, m);
        increment = {{"from_s", d.from_s},
                     {"to_s", d.to_s},
                     {"delta_velocity_mps", vectorJson(d.deltaVelocity_m_per_s)},
                     {"delta_angle_rad", vectorJson(d.deltaAngle_rad)}};
    }
    return {{"time_s", m.time_s},
            {"axes", "the [camera]'s: x right, y up, z back"},
            {"position_m", vectorJson(turn * m.position_m)},
            {"orientation_wxyz", {orientation.w, orientation.x, orientation.y, orientation.z}},
            {"world_from_platform", matrixJson(glm::dmat4(turn) * worldFromPlatform(m))},
            {"heading_deg", std::fmod(std::fmod(platform.yaw_deg, 360.0) + 360.0, 360.0)},
            {"pitch_deg", platform.pitch_deg},
            {"roll_deg", platform.roll_deg},
            {"linear_velocity_mps", vectorJson(turn * m.velocity_m_per_s)},
            {"angular_velocity_radps", vectorJson(turn * m.angularVelocity_rad_per_s)},
            {"linear_acceleration_mps2", vectorJson(turn * m.acceleration_m_per_s2)},
            {"imu",
             {{"specific_force_mps2", vectorJson(imu.specificForce_m_per_s2)},
              {"angular_rate_radps", vectorJson(imu.angularRate_rad_per_s)},
              {"gravity_mps2", kGravity},
              {"increment", increment}}}};
}

Json rigJson(const std::string& name, const CameraCalibration& camera, const PlatformMotion& motion,
             const std::vector<std::string>& cameras)
{
    // Both transforms in Swell's axes: the world frame's turn cancels.
    const glm::dmat4 platformFromCamera = glm::affineInverse(worldFromPlatform(motion)) * camera.worldFromCamera;
    return {{"camera", name},
            {"cameras", cameras},
            {"platform_from_camera", matrixJson(platformFromCamera)},
            {"camera_from_platform", matrixJson(glm::affineInverse(platformFromCamera))}};
}

} // namespace swell::app
