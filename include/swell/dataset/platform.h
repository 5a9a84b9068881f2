// The platform a rig of cameras rides, and its ground truth
// (docs/LABELS.md, "Rigs and the platform"): the platform is what the
// scene's [camera] places (fixed, on its path, or riding a body with
// camera.mount_object); its axes are that camera's own, x right, y up and z
// back (the world's axes at yaw, pitch and roll 0: x east, y up, z south).
// Each [[camera.rig]] camera stands at its offset in those axes, turned from
// them by its own yaw, pitch and roll.
//
// An IMU fixed to the platform at its origin reads, in the platform's axes,
//   specific force  f = R^T (a - g),   g = (0, -kGravity, 0) (world, y up)
//   angular rate    w_p = R^T w
// with R the platform's orientation (platform to world), a its origin's
// acceleration and w its angular velocity, world axes: at rest and level it
// reads f = (0, +9.80665, 0), up (Titterton & Weston 2004, "Strapdown
// Inertial Navigation Technology", 2nd ed., sec. 3.2: the accelerometer
// measures specific force, the acceleration less the gravitational field).
#pragma once

#include "swell/export.h"

#include "swell/camera.h"
#include "swell/scene/scene.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace swell {

// How the platform stands and moves at one time, world (Swell's) axes.
struct SWELL_API PlatformMotion {
    double time_s = 0.0;
    glm::dvec3 position_m{0.0};                   // its origin: the [camera]'s eye, m
    glm::dquat orientation{1.0, 0.0, 0.0, 0.0};   // platform axes to world axes
    glm::dvec3 velocity_m_per_s{0.0};             // its origin's, m/s
    glm::dvec3 angularVelocity_rad_per_s{0.0};    // rad/s
    glm::dvec3 acceleration_m_per_s2{0.0};        // its origin's, m/s^2 (gravity not included)
};

// What an ideal IMU at the platform's origin reads (the equations above),
// in the platform's axes.
struct SWELL_API ImuReading {
    glm::dvec3 specificForce_m_per_s2{0.0}; // m/s^2; (0, +g, 0) at rest and level
    glm::dvec3 angularRate_rad_per_s{0.0};  // rad/s
};

SWELL_API ImuReading imuReadingOf(const PlatformMotion& motion);

// What a strapdown IMU reports between two frames, integrated inside the IMU
// over the whole interval [t0, t1] (its coning and sculling taken into
// account, as IMUs that output increments do), in the platform's axes at
// t0, with R(t) its orientation and v(t) its velocity (world):
//   delta velocity  dv = integral over [t0, t1] of R(t0)^T R(t) f(t) dt
//                      = R(t0)^T (v(t1) - v(t0) - g (t1 - t0))
//   delta angle     da = the rotation vector of R(t0)^T R(t1):
//                        R(t1) = R(t0) exp(da), the integral of the angular
//                        rate w_p wherever its axis holds still over the interval
// Integrated back (Titterton & Weston 2004, sec. 3.5, the velocity and
// attitude updates from increments):
//   R(t1) = R(t0) exp(da),   v(t1) = v(t0) + R(t0) dv + g (t1 - t0)
// exact for the attitude and velocity; the position then follows from the
// velocities (trapezoidal rule: p(t1) = p(t0) + (v(t0) + v(t1)) (t1 - t0) / 2).
// Unlike the instantaneous readings above, sampled at a frame rate these
// do not alias the waves' motion between the samples.
struct SWELL_API ImuIncrement {
    double from_s = 0.0, to_s = 0.0;          // t0 and t1, s
    glm::dvec3 deltaVelocity_m_per_s{0.0};    // dv, m/s
    glm::dvec3 deltaAngle_rad{0.0};           // da, rad
};

// The increment from the platform's state `from` to its state `to` (later).
SWELL_API ImuIncrement imuIncrementOf(const PlatformMotion& from, const PlatformMotion& to);

// The camera's axes (x right, y up, z back) to the world's: its orientation
// as a platform.
SWELL_API glm::dquat platformOrientationOf(const Camera& camera);
// The platform's transform, platform axes to world, m.
SWELL_API glm::dmat4 worldFromPlatform(const PlatformMotion& motion);

// A rig camera placed on the platform the camera `platform` stands for: at
// rig.position_m in its axes, turned by rig's yaw, pitch and roll from them,
// with rig's field of view (the platform's when rig.fovY_deg is 0).
SWELL_API Camera rigCameraOf(const Camera& platform, const RigCamera& rig);

// The motion of a camera that is not mounted: fixed, or on its path
// (cameraAt()). A path's keys are joined linearly: between two keys the
// velocity is their difference over their times and the acceleration 0;
// at a key, the segment after it counts; before the first key and from the
// last one on, it stands. The angular velocity is that of the orientation
// the path interpolates (its angles', turned into a vector), within the
// segment.
SWELL_API PlatformMotion unmountedCameraMotion(const CameraSettings& settings, double time_s);

} // namespace swell
