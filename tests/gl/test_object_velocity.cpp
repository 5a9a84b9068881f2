// Each object's velocity in the labels (swell/dataset/labels.h ObjectLabel,
// docs/LABELS.md "objects"; issue 46, item 4): a floating rigid body's
// linear and angular velocity, from the simulation's state, against finite
// differences of the poses the labels write at t and t + dt. dt = 2 ms lies
// inside one body step (1/120 s), over which the drawn pose moves at the
// state's velocities: what is left is the lever arm's turn during dt
// (|w|^2 |r| dt / 2, under 1e-4 m/s here) and the differences' rounding, so
// the bound is 1e-3 m/s and 1e-3 rad/s (a velocity from the step before or
// after, off by the body's acceleration times a step, misses it by 1e-2 or
// more). A boat under way at 3 m/s, a buoy let go 0.5 m above its rest,
// heaving; a fixed rock at rest; a float without a body of its own unknown.
#include "support/gl_test.h"

#include "support/open_sea.h"
#include "swell/dataset/labels.h"
#include "swell/renderer.h"
#include "swell/scene/scene.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <cstdio>

namespace {

class ObjectVelocity : public swell::test::GlTest {};

swell::FrameLabels labelsAt(swell::Renderer& renderer, double time_s)
{
    swell::Camera camera;
    camera.position_m = glm::dvec3(0.0, 8.0, 10.0);
    camera.pitch_deg = -15.0;
    renderer.advanceTo(time_s, camera.position_m);
    return renderer.renderLabels(camera, {32, 24});
}

// The rotation's axis times its rate from two rotations dt apart (the
// skew part of R(t + dt) R(t)^T, for a turn small enough that sin = angle).
glm::dvec3 angularRate(const glm::dmat4& before, const glm::dmat4& after, double dt_s)
{
    const glm::dmat3 turn = glm::dmat3(after) * glm::transpose(glm::dmat3(before));
    return 0.5 / dt_s * glm::dvec3(turn[1][2] - turn[2][1], turn[2][0] - turn[0][2], turn[0][1] - turn[1][0]);
}

TEST_F(ObjectVelocity, IsTheDerivativeOfTheWrittenPoses)
{
    swell::Scene scene = swell::test::openSea();
    scene.historyStart_s = 0.0; // the bodies start at t = 0: their steps at multiples of 1/120 s
    scene.wake.enabled = false;
    swell::SceneObject boat;
    boat.path = "builtin:boat";
    boat.floats = true;
    boat.density_kg_per_m3 = 400.0;
    boat.position_m = glm::dvec3(-4.0, 0.0, -12.0);
    boat.yaw_deg = 20.0;
    boat.velocity_m_per_s = glm::dvec3(3.0, 0.0, -1.0);
    swell::SceneObject buoy;
    buoy.path = "builtin:buoy";
    buoy.floats = true;
    buoy.density_kg_per_m3 = 400.0;
    buoy.position_m = glm::dvec3(5.0, 0.5, -15.0); // let go 0.5 m above its rest
    swell::SceneObject rock;
    rock.path = "builtin:rock";
    rock.position_m = glm::dvec3(0.0, -1.0, -30.0);
    swell::SceneObject riding = buoy; // rides the water, no body of its own
    riding.density_kg_per_m3 = 0.0;
    riding.position_m = glm::dvec3(-8.0, 0.0, -25.0);
    scene.objects = {boat, buoy, rock, riding};
    swell::Renderer renderer(scene);

    const double t_s = 1.5 + 0.25 / 120.0, dt_s = 0.002; // inside the body step [180, 181] / 120 s
    const swell::FrameLabels now = labelsAt(renderer, t_s);
    const swell::FrameLabels next = labelsAt(renderer, t_s + dt_s);
    ASSERT_EQ(now.objects.size(), 4u);
    for (std::size_t i = 0; i < 2; ++i) {
        const swell::ObjectLabel& a = now.objects[i];
        const swell::ObjectLabel& b = next.objects[i];
        ASSERT_TRUE(a.velocityKnown) << i;
        const glm::dvec3 linear = (b.pose.position_m - a.pose.position_m) / dt_s;
        const glm::dvec3 angular = angularRate(a.pose.worldFromObject, b.pose.worldFromObject, dt_s);
        EXPECT_LT(glm::distance(a.velocity_m_per_s, linear), 1e-3)
            << i << ": written " << a.velocity_m_per_s.x << ", " << a.velocity_m_per_s.y << ", " << a.velocity_m_per_s.z
            << "; poses " << linear.x << ", " << linear.y << ", " << linear.z;
        EXPECT_LT(glm::distance(a.angularVelocity_rad_per_s, angular), 1e-3)
            << i << ": written " << a.angularVelocity_rad_per_s.x << ", " << a.angularVelocity_rad_per_s.y << ", "
            << a.angularVelocity_rad_per_s.z << "; poses " << angular.x << ", " << angular.y << ", " << angular.z;
        std::printf("object %zu: v %.4f %.4f %.4f m/s (poses %.4f %.4f %.4f), w %.4f %.4f %.4f rad/s (poses %.4f %.4f %.4f)\n",
                    i, a.velocity_m_per_s.x, a.velocity_m_per_s.y, a.velocity_m_per_s.z, linear.x, linear.y, linear.z,
                    a.angularVelocity_rad_per_s.x, a.angularVelocity_rad_per_s.y, a.angularVelocity_rad_per_s.z,
                    angular.x, angular.y, angular.z);
    }
    // Under way: carried at its 3 m/s; heaving: the buoy moves up or down.
    EXPECT_NEAR(now.objects[0].velocity_m_per_s.x, 3.0, 0.05);
    EXPECT_GT(std::abs(now.objects[1].velocity_m_per_s.y), 0.05) << "the buoy does not heave";
    // Fixed: at rest and known; riding the water without a body: not known.
    EXPECT_TRUE(now.objects[2].velocityKnown);
    EXPECT_EQ(glm::length(now.objects[2].velocity_m_per_s) + glm::length(now.objects[2].angularVelocity_rad_per_s), 0.0);
    EXPECT_FALSE(now.objects[3].velocityKnown);
}

} // namespace
