#include "swell/dataset/platform.h"

#include "swell/constants.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace swell {

ImuReading imuReadingOf(const PlatformMotion& m)
{
    const glm::dquat toPlatform = glm::conjugate(m.orientation);
    const glm::dvec3 gravity(0.0, -kGravity, 0.0);
    return {toPlatform * (m.acceleration_m_per_s2 - gravity), toPlatform * m.angularVelocity_rad_per_s};
}

ImuIncrement imuIncrementOf(const PlatformMotion& from, const PlatformMotion& to)
{
    const glm::dquat toPlatform = glm::conjugate(from.orientation);
    const glm::dvec3 gravity(0.0, -kGravity, 0.0);
    const double interval_s = to.time_s - from.time_s;
    ImuIncrement increment;
    increment.from_s = from.time_s;
    increment.to_s = to.time_s;
    increment.deltaVelocity_m_per_s =
        toPlatform * (to.velocity_m_per_s - from.velocity_m_per_s - gravity * interval_s);
    // The turn R(t0)^T R(t1) as a rotation vector: its shorter way round.
    glm::dquat turn = glm::normalize(toPlatform * to.orientation);
    if (turn.w < 0.0)
        turn = -turn;
    const glm::dvec3 axis(turn.x, turn.y, turn.z);
    const double half = std::atan2(glm::length(axis), turn.w);
    increment.deltaAngle_rad = half > 0.0 ? axis * (2.0 * half / glm::length(axis)) : glm::dvec3(0.0);
    return increment;
}

glm::dquat platformOrientationOf(const Camera& camera)
{
    // The view matrix turns world axes into the camera's; its transpose back.
    const glm::dmat3 view(camera.viewRelativeTo(camera.position_m));
    return glm::normalize(glm::quat_cast(glm::transpose(view)));
}

glm::dmat4 worldFromPlatform(const PlatformMotion& m)
{
    return glm::translate(glm::dmat4(1.0), m.position_m) * glm::mat4_cast(m.orientation);
}

Camera rigCameraOf(const Camera& platform, const RigCamera& rig)
{
    Camera relative = platform;
    relative.position_m = rig.position_m;
    relative.yaw_deg = rig.yaw_deg;
    relative.pitch_deg = rig.pitch_deg;
    relative.roll_deg = rig.roll_deg;
    if (rig.fovY_deg > 0.0)
        relative.fovY_deg = rig.fovY_deg;
    const glm::dmat4 world = glm::translate(glm::dmat4(1.0), platform.position_m) *
                             glm::mat4_cast(platformOrientationOf(platform));
    return mountedCamera(relative, world);
}

PlatformMotion unmountedCameraMotion(const CameraSettings& settings, double time_s)
{
    PlatformMotion m;
    m.time_s = time_s;
    const Camera camera = cameraAt(settings, time_s);
    m.position_m = camera.position_m;
    m.orientation = platformOrientationOf(camera);
    const auto& path = settings.path;
    if (path.size() < 2 || time_s < path.front().time_s || time_s >= path.back().time_s)
        return m;
    const auto next = std::upper_bound(path.begin(), path.end(), time_s,
                                       [](double t, const CameraKey& k) { return t < k.time_s; });
    const CameraKey& a = *(next - 1);
    const CameraKey& b = *next;
    m.velocity_m_per_s = (b.position_m - a.position_m) / (b.time_s - a.time_s);
    // The turn over a short span inside the segment (its angles change
    // linearly there, so the rate is smooth): w = 2 log(q1 q0^-1) / dt.
    const double span_s = std::min(1e-4, 0.25 * (b.time_s - a.time_s));
    const double t0 = std::max(a.time_s, time_s - span_s), t1 = std::min(b.time_s, time_s + span_s);
    const glm::dquat q0 = platformOrientationOf(cameraAt(settings, t0));
    const glm::dquat q1 = platformOrientationOf(cameraAt(settings, t1));
    glm::dquat turn = q1 * glm::conjugate(q0);
    if (turn.w < 0.0)
        turn = -turn;
    const glm::dvec3 axis(turn.x, turn.y, turn.z);
    const double sinHalf = glm::length(axis);
    if (sinHalf > 0.0)
        m.angularVelocity_rad_per_s = axis / sinHalf * (2.0 * std::atan2(sinHalf, turn.w) / (t1 - t0));
    return m;
}

} // namespace swell
