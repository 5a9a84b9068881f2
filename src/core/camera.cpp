#include "swell/camera.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace swell {

glm::dvec3 Camera::forward() const
{
    const double yaw = glm::radians(yaw_deg), pitch = glm::radians(std::clamp(pitch_deg, -89.9, 89.9));
    return {std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch)};
}

glm::dmat4 Camera::viewRelativeTo(glm::dvec3 origin_m) const
{
    const glm::dvec3 eye = position_m - origin_m;
    // Up turned about the view direction by the roll (Rodrigues' rotation:
    // v cos r + (f x v) sin r + f (f . v)(1 - cos r)); exactly +y at roll 0.
    const glm::dvec3 f = forward(), worldUp(0.0, 1.0, 0.0);
    const double r = glm::radians(roll_deg);
    const glm::dvec3 up =
        worldUp * std::cos(r) + glm::cross(f, worldUp) * std::sin(r) + f * glm::dot(f, worldUp) * (1.0 - std::cos(r));
    return glm::lookAt(eye, eye + f, up);
}

glm::dmat4 Camera::projection(double aspect) const
{
    return glm::perspective(glm::radians(fovY_deg), aspect, near_m, far_m);
}

Camera mountedCamera(const Camera& relative, const glm::dmat4& objectToWorld)
{
    // The object's rotation, its scale taken out of each axis.
    glm::dmat3 rotation(objectToWorld);
    for (int c = 0; c < 3; ++c)
        rotation[c] = glm::normalize(rotation[c]);
    const double scale = glm::length(glm::dvec3(objectToWorld[0]));
    // The relative camera's forward and up in the object's axes (its view
    // matrix's rows), turned into the world's.
    const glm::dmat3 viewRotation(relative.viewRelativeTo(relative.position_m));
    const glm::dvec3 forward = rotation * -glm::dvec3(viewRotation[0][2], viewRotation[1][2], viewRotation[2][2]);
    const glm::dvec3 up = rotation * glm::dvec3(viewRotation[0][1], viewRotation[1][1], viewRotation[2][1]);
    Camera c = relative;
    c.position_m = glm::dvec3(objectToWorld * glm::dvec4(relative.position_m / scale, 1.0));
    c.yaw_deg = glm::degrees(std::atan2(forward.x, -forward.z));
    c.pitch_deg = glm::degrees(std::asin(std::clamp(forward.y, -1.0, 1.0)));
    // The roll that turns the level up (the world's up, square to forward)
    // into the camera's about forward (viewRelativeTo's Rodrigues rotation).
    const glm::dvec3 worldUp(0.0, 1.0, 0.0);
    const glm::dvec3 level = worldUp - forward * glm::dot(forward, worldUp);
    const double levelLength = glm::length(level);
    c.roll_deg = levelLength > 1e-9 ? glm::degrees(std::atan2(glm::dot(up, glm::cross(forward, level / levelLength)),
                                                              glm::dot(up, level / levelLength)))
                                    : 0.0;
    return c;
}

Camera cameraAt(const CameraSettings& s, double time_s)
{
    Camera c;
    c.position_m = s.position_m;
    c.yaw_deg = s.yaw_deg;
    c.pitch_deg = s.pitch_deg;
    c.roll_deg = s.roll_deg;
    c.fovY_deg = s.fovY_deg;
    c.near_m = s.near_m;
    c.far_m = s.far_m;
    if (s.path.empty())
        return c;
    const auto& path = s.path;
    auto apply = [&c](const CameraKey& k) {
        c.position_m = k.position_m;
        c.yaw_deg = k.yaw_deg;
        c.pitch_deg = k.pitch_deg;
        c.roll_deg = k.roll_deg;
    };
    if (time_s <= path.front().time_s) {
        apply(path.front());
        return c;
    }
    if (time_s >= path.back().time_s) {
        apply(path.back());
        return c;
    }
    const auto next = std::upper_bound(path.begin(), path.end(), time_s,
                                       [](double t, const CameraKey& k) { return t < k.time_s; });
    const CameraKey& a = *(next - 1);
    const CameraKey& b = *next;
    const double f = (time_s - a.time_s) / std::max(b.time_s - a.time_s, 1e-9);
    c.position_m = glm::mix(a.position_m, b.position_m, f);
    c.yaw_deg = a.yaw_deg + (b.yaw_deg - a.yaw_deg) * f;
    c.pitch_deg = a.pitch_deg + (b.pitch_deg - a.pitch_deg) * f;
    c.roll_deg = a.roll_deg + (b.roll_deg - a.roll_deg) * f;
    return c;
}

} // namespace swell
