// The platform's ground truth (swell/dataset/platform.h, docs/LABELS.md
// "Rigs and the platform"; issue 46, item 3): what an IMU on the platform
// reads integrates back to the platform's poses. A camera platform rides a
// workboat under way through a wind sea, 1.5 m to port of and 2.5 m above
// the boat's origin (a lever arm whose turn adds to the acceleration), and
// its written readings, sampled at the body's step rate (120 Hz) half
// way through each step (a clip at 120 frames a second whose frames fall
// there), are integrated by strapdown navigation (Titterton & Weston 2004,
// "Strapdown Inertial Navigation Technology", ch. 3): the angular rate on
// the orientation quaternion, the specific force turned into the world with
// it and gravity added back, integrated twice, all by the trapezoidal rule
// from the first written pose and velocity. Over 10 s the result must stay
// with the written poses: kPositionDrift_m, kAttitudeDrift_deg and
// kVelocityDrift_mps below (measured: 0.137 m, 0.026 m/s, 0.0003 deg).
// Why mid-step, at the step rate: inside a step the drawn pose moves at
// the step's velocities and the readings are constant, and they change at
// the step's ends; samples there integrate to the poses (the turn exactly),
// what is left being the trapezoid's half step against those changes, which
// the first sample's acceleration carries into the position. The same
// integration of readings 30 times a second, on the steps' ends, drifts
// 0.87 m, 0.17 m/s and 0.18 deg over the same 10 s (printed too): the
// readings are the instant's, not the interval's (docs/LABELS.md).
#include "support/gl_test.h"

#include "support/open_sea.h"
#include "swell/constants.h"
#include "swell/dataset/platform.h"
#include "swell/floating_body.h"
#include "swell/renderer.h"
#include "swell/scene/scene.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace {

class PlatformImu : public swell::test::GlTest {};

// The drift allowed after 10 s of integration at 120 Hz, mid-step.
constexpr double kPositionDrift_m = 0.25;
constexpr double kVelocityDrift_mps = 0.05;
constexpr double kAttitudeDrift_deg = 0.01;

swell::Scene boatPlatform()
{
    swell::Scene scene = swell::test::openSea();
    scene.historyStart_s = 0.0; // the body starts at t = 0 and settles into the sea while it is integrated
    scene.wake.enabled = false;
    swell::SceneObject boat;
    boat.path = "builtin:boat";
    boat.floats = true;
    boat.density_kg_per_m3 = 400.0;
    boat.position_m = glm::dvec3(0.0, 0.3, -10.0); // let go 0.3 m above its rest: it heaves as it rolls
    boat.yaw_deg = 30.0;
    boat.velocity_m_per_s = glm::dvec3(2.0, 0.0, -1.0);
    scene.objects = {boat};
    scene.camera.mountObject = 0;
    scene.camera.mountOffset_m = glm::dvec3(0.5, 2.5, -1.5);
    scene.camera.yaw_deg = -70.0; // looking to port, turned from the boat's axes
    scene.camera.pitch_deg = -10.0;
    return scene;
}

// exp of a rotation vector (rad) as a unit quaternion.
glm::dquat rotationOf(glm::dvec3 v)
{
    const double angle = glm::length(v);
    if (angle < 1e-15)
        return {1.0, 0.0, 0.0, 0.0};
    return glm::angleAxis(angle, v / angle);
}

double angleBetween_deg(const glm::dquat& a, const glm::dquat& b)
{
    const double c = std::min(1.0, std::abs(glm::dot(a, b)));
    return glm::degrees(2.0 * std::acos(c));
}

struct Drift {
    double position_m = 0.0, velocity_mps = 0.0, attitude_deg = 0.0;
};

// Strapdown integration of the platform's IMU over samples dt apart, from
// the first sample's pose and velocity; the largest differences from the
// written poses and velocities. `readings` lets a test break the IMU.
Drift integrate(const std::vector<swell::PlatformMotion>& written, const std::vector<swell::ImuReading>& readings,
                double dt_s)
{
    const glm::dvec3 gravity(0.0, -swell::kGravity, 0.0);
    glm::dquat q = written.front().orientation;
    glm::dvec3 v = written.front().velocity_m_per_s, p = written.front().position_m;
    glm::dvec3 acceleration = q * readings.front().specificForce_m_per_s2 + gravity;
    Drift drift;
    for (std::size_t k = 0; k + 1 < written.size(); ++k) {
        // The body rate is in the platform's axes: the turn multiplies on the right.
        const glm::dvec3 rate = 0.5 * (readings[k].angularRate_rad_per_s + readings[k + 1].angularRate_rad_per_s);
        q = glm::normalize(q * rotationOf(rate * dt_s));
        const glm::dvec3 nextAcceleration = q * readings[k + 1].specificForce_m_per_s2 + gravity;
        const glm::dvec3 nextV = v + 0.5 * dt_s * (acceleration + nextAcceleration);
        p += 0.5 * dt_s * (v + nextV);
        v = nextV;
        acceleration = nextAcceleration;
        const swell::PlatformMotion& truth = written[k + 1];
        drift.position_m = std::max(drift.position_m, glm::length(p - truth.position_m));
        drift.velocity_mps = std::max(drift.velocity_mps, glm::length(v - truth.velocity_m_per_s));
        drift.attitude_deg = std::max(drift.attitude_deg, angleBetween_deg(q, truth.orientation));
    }
    return drift;
}

TEST_F(PlatformImu, IntegratesBackToTheWrittenPosesOver10s)
{
    swell::Renderer renderer(boatPlatform());
    const double start_s = 2.0, span_s = 10.0;
    const auto sample = [&](double fps, double offset_s, std::vector<swell::PlatformMotion>& written,
                            std::vector<swell::ImuReading>& readings) {
        for (int k = 0; k <= int(span_s * fps); ++k) {
            written.push_back(renderer.platformAt(start_s + offset_s + double(k) / fps));
            readings.push_back(swell::imuReadingOf(written.back()));
        }
    };
    std::vector<swell::PlatformMotion> frames, written;
    std::vector<swell::ImuReading> frameReadings, readings;
    sample(30.0, 0.0, frames, frameReadings);
    renderer.setScene(boatPlatform()); // the bodies start again for the second pass
    const double fps = double(swell::kBodyStepsPerSecond);
    sample(fps, 0.5 / fps, written, readings);
    const Drift framesDrift = integrate(frames, frameReadings, 1.0 / 30.0);
    std::printf("the same at 30 Hz on the steps' ends: position %.4f m, velocity %.4f m/s, attitude %.4f deg off\n",
                framesDrift.position_m, framesDrift.velocity_mps, framesDrift.attitude_deg);
    // The platform moves: under way, heaving, rolling and pitching.
    double largestRate = 0.0, largestVertical = 0.0;
    for (const swell::ImuReading& r : readings) {
        largestRate = std::max(largestRate, glm::length(r.angularRate_rad_per_s));
        largestVertical = std::max(largestVertical, std::abs(glm::length(r.specificForce_m_per_s2) - swell::kGravity));
    }
    EXPECT_GT(largestRate, 0.05);
    EXPECT_GT(largestVertical, 0.2);
    const Drift drift = integrate(written, readings, 1.0 / fps);
    std::printf("IMU integrated over 10 s at 120 Hz, mid-step: position %.4f m, velocity %.4f m/s, attitude %.4f deg off; "
                "largest rate %.3f rad/s, |f| - g up to %.3f m/s^2\n",
                drift.position_m, drift.velocity_mps, drift.attitude_deg, largestRate, largestVertical);
    EXPECT_LT(drift.position_m, kPositionDrift_m);
    EXPECT_LT(drift.velocity_mps, kVelocityDrift_mps);
    EXPECT_LT(drift.attitude_deg, kAttitudeDrift_deg);
    // The written velocity is the poses' derivative (a central difference
    // over one frame: the motion's curvature leaves millimetres a second).
    for (std::size_t k = 1; k + 1 < written.size(); ++k) {
        const glm::dvec3 difference = (written[k + 1].position_m - written[k - 1].position_m) * (0.5 * fps);
        EXPECT_LT(glm::length(difference - written[k].velocity_m_per_s), 0.05) << k;
    }
}

// Strapdown integration of per-frame increments (swell::ImuIncrement, the
// recipe platform.h gives): the attitude and velocity updates from each
// increment, the position by the trapezoidal rule on the velocities.
Drift integrateIncrements(const std::vector<swell::PlatformMotion>& written,
                          const std::vector<swell::ImuIncrement>& increments)
{
    const glm::dvec3 gravity(0.0, -swell::kGravity, 0.0);
    glm::dquat q = written.front().orientation;
    glm::dvec3 v = written.front().velocity_m_per_s, p = written.front().position_m;
    Drift drift;
    for (std::size_t k = 0; k + 1 < written.size(); ++k) {
        const swell::ImuIncrement& d = increments[k];
        const double dt_s = d.to_s - d.from_s;
        const glm::dvec3 nextV = v + q * d.deltaVelocity_m_per_s + gravity * dt_s;
        q = glm::normalize(q * rotationOf(d.deltaAngle_rad));
        p += 0.5 * dt_s * (v + nextV);
        v = nextV;
        const swell::PlatformMotion& truth = written[k + 1];
        drift.position_m = std::max(drift.position_m, glm::length(p - truth.position_m));
        drift.velocity_mps = std::max(drift.velocity_mps, glm::length(v - truth.velocity_m_per_s));
        drift.attitude_deg = std::max(drift.attitude_deg, angleBetween_deg(q, truth.orientation));
    }
    return drift;
}

// The drift allowed after 10 s of a 30 Hz clip's increments: within what
// the instantaneous readings give at the body's own 120 Hz (0.137 m).
constexpr double kClipPositionDrift_m = 0.05;
constexpr double kClipVelocityDrift_mps = 0.001;
constexpr double kClipAttitudeDrift_deg = 0.001;

// A 30 Hz clip's per-frame increments (docs/LABELS.md, the platform's
// `imu.increment`), integrated over 10 s, stay with the written poses where
// its instantaneous readings drift 0.87 m; the under-way boat of the test
// above, sampled on the steps' ends and, as a clip may, between them.
TEST_F(PlatformImu, ClipIncrementsAt30HzIntegrateBackOver10s)
{
    for (double offset_s : {0.0, 0.37 / double(swell::kBodyStepsPerSecond)}) {
        swell::Renderer renderer(boatPlatform());
        const double start_s = 2.0 + offset_s, span_s = 10.0, fps = 30.0;
        std::vector<swell::PlatformMotion> frames;
        std::vector<swell::ImuIncrement> increments;
        double turned_deg = 0.0, changed_mps = 0.0;
        for (int k = 0; k <= int(span_s * fps); ++k) {
            frames.push_back(renderer.platformAt(start_s + double(k) / fps));
            if (k > 0) {
                increments.push_back(swell::imuIncrementOf(frames[frames.size() - 2], frames.back()));
                turned_deg = std::max(turned_deg, glm::degrees(glm::length(increments.back().deltaAngle_rad)));
                changed_mps = std::max(changed_mps, glm::length(increments.back().deltaVelocity_m_per_s));
                EXPECT_NEAR(increments.back().to_s - increments.back().from_s, 1.0 / fps, 1e-12);
            }
        }
        // A frame's turn and velocity change are more than rounding.
        EXPECT_GT(turned_deg, 0.1);
        EXPECT_GT(changed_mps, 0.3);
        const Drift drift = integrateIncrements(frames, increments);
        std::printf("increments of a 30 Hz clip (frames %.4f s past the steps' ends) integrated over 10 s: position "
                    "%.4f m, velocity %.6f m/s, attitude %.6f deg off\n",
                    offset_s, drift.position_m, drift.velocity_mps, drift.attitude_deg);
        EXPECT_LT(drift.position_m, kClipPositionDrift_m);
        EXPECT_LT(drift.velocity_mps, kClipVelocityDrift_mps);
        EXPECT_LT(drift.attitude_deg, kClipAttitudeDrift_deg);
    }
}

// At rest the increments are gravity's reaction over the interval and no turn;
// a steady turn at a rate w about a fixed axis is w dt.
TEST_F(PlatformImu, IncrementsOfRestAndOfASteadyTurn)
{
    swell::PlatformMotion a, b;
    a.time_s = 1.0;
    b.time_s = 1.5;
    a.orientation = b.orientation = glm::angleAxis(0.3, glm::normalize(glm::dvec3(1.0, 2.0, 0.5)));
    const swell::ImuIncrement rest = swell::imuIncrementOf(a, b);
    const glm::dvec3 up = glm::conjugate(a.orientation) * glm::dvec3(0.0, swell::kGravity * 0.5, 0.0);
    EXPECT_LT(glm::length(rest.deltaVelocity_m_per_s - up), 1e-12);
    EXPECT_LT(glm::length(rest.deltaAngle_rad), 1e-12);
    const glm::dvec3 rate(0.2, -0.4, 0.1); // platform axes, rad/s
    b.orientation = a.orientation * rotationOf(rate * 0.5);
    EXPECT_LT(glm::length(swell::imuIncrementOf(a, b).deltaAngle_rad - rate * 0.5), 1e-12);
}

TEST_F(PlatformImu, ReadsGravityUpAtRest)
{
    // A fixed, level camera: +g along the platform's y (up), no rate; pitched
    // 30 degrees down, gravity's reaction leans towards its back (+z).
    swell::Scene scene = swell::test::openSea();
    scene.camera.position_m = glm::dvec3(3.0, 10.0, -4.0);
    scene.camera.yaw_deg = 40.0;
    scene.camera.pitch_deg = 0.0;
    swell::Renderer renderer(scene);
    swell::ImuReading level = swell::imuReadingOf(renderer.platformAt(5.0));
    EXPECT_LT(glm::length(level.specificForce_m_per_s2 - glm::dvec3(0.0, swell::kGravity, 0.0)), 1e-9);
    EXPECT_LT(glm::length(level.angularRate_rad_per_s), 1e-12);
    scene.camera.pitch_deg = -30.0;
    renderer.setScene(scene);
    const swell::ImuReading pitched = swell::imuReadingOf(renderer.platformAt(5.0));
    const double s = std::sin(glm::radians(30.0)), c = std::cos(glm::radians(30.0));
    EXPECT_LT(glm::length(pitched.specificForce_m_per_s2 - swell::kGravity * glm::dvec3(0.0, c, s)), 1e-9)
        << pitched.specificForce_m_per_s2.y << " " << pitched.specificForce_m_per_s2.z;
}

// A rig camera stands at its offset in the platform's axes and turns with it.
TEST_F(PlatformImu, RigCamerasStandOnThePlatform)
{
    swell::Camera platform;
    platform.position_m = glm::dvec3(10.0, 5.0, -3.0);
    platform.yaw_deg = 90.0; // facing east: its right is south (+z)
    platform.pitch_deg = 0.0;
    swell::RigCamera right;
    right.position_m = glm::dvec3(0.3, 0.0, 0.0);
    const swell::Camera camera = swell::rigCameraOf(platform, right);
    EXPECT_LT(glm::length(camera.position_m - glm::dvec3(10.0, 5.0, -2.7)), 1e-12);
    EXPECT_NEAR(camera.yaw_deg, 90.0, 1e-9);
    EXPECT_NEAR(camera.fovY_deg, platform.fovY_deg, 1e-12);
}

} // namespace
