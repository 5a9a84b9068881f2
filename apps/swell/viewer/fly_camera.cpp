// Fly-camera motion: turn by cursor movement, move along the view and world up.
#include "viewer/fly_camera.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace swell::app::viewer {

void FlyCamera::setLens(double fovY_deg, double near_m, double far_m)
{
    camera_.fovY_deg = fovY_deg;
    camera_.near_m = near_m;
    camera_.far_m = far_m;
}

void FlyCamera::setSpeed(double speed_mps) { speed_mps_ = std::clamp(speed_mps, kMinSpeed_mps, kMaxSpeed_mps); }

bool FlyCamera::moves(const FlyInput& input)
{
    return input.look_px != glm::dvec2(0.0) || input.move != glm::dvec3(0.0);
}

void FlyCamera::update(const FlyInput& input, double dt_s)
{
    if (input.wheel != 0.0)
        setSpeed(speed_mps_ * std::pow(kWheelFactor, input.wheel));

    // Heading wraps to -180..180 so it stays inside the scene file's range
    // when saved; pitch stops short of straight up or down.
    double yaw = camera_.yaw_deg + input.look_px.x * kLookDegPerPixel;
    yaw = std::remainder(yaw, 360.0);
    camera_.yaw_deg = yaw;
    camera_.pitch_deg = std::clamp(camera_.pitch_deg - input.look_px.y * kLookDegPerPixel, -89.0, 89.0);

    if (input.move == glm::dvec3(0.0) || dt_s <= 0.0)
        return;
    // forward() is (sin yaw cos pitch, sin pitch, -cos yaw cos pitch), so the
    // horizontal right-hand direction is (cos yaw, 0, sin yaw).
    const double yawRad = camera_.yaw_deg * (3.14159265358979323846 / 180.0);
    const glm::dvec3 right(std::cos(yawRad), 0.0, std::sin(yawRad));
    const glm::dvec3 up(0.0, 1.0, 0.0);
    glm::dvec3 direction = right * input.move.x + up * input.move.y + camera_.forward() * input.move.z;
    if (glm::length(direction) > 1e-9)
        direction = glm::normalize(direction);
    const double speed = speed_mps_ * (input.fast ? kFastFactor : 1.0);
    camera_.position_m += direction * (speed * dt_s);
}

} // namespace swell::app::viewer
