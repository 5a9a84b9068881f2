// A camera on a deck (swell/camera.h's mountedCamera): it stands at its
// offset in the object's axes and looks along its own forward and up turned
// by the object, whatever the object's heading, heel and trim; a scaled
// object does not scale the offset.
#include "swell/camera.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace {

glm::dvec3 forwardOf(const swell::Camera& c)
{
    const glm::dmat3 r(c.viewRelativeTo(c.position_m));
    return -glm::dvec3(r[0][2], r[1][2], r[2][2]);
}

glm::dvec3 upOf(const swell::Camera& c)
{
    const glm::dmat3 r(c.viewRelativeTo(c.position_m));
    return glm::dvec3(r[0][1], r[1][1], r[2][1]);
}

TEST(CameraMount, TheCameraTurnsAndMovesWithItsObject)
{
    swell::Camera relative;
    relative.position_m = glm::dvec3(0.5, 3.0, -1.5);
    for (double yaw : {0.0, 35.0, -120.0})
        for (double pitch : {0.0, -10.0, 20.0})
            for (double roll : {0.0, 15.0}) {
                relative.yaw_deg = yaw;
                relative.pitch_deg = pitch;
                relative.roll_deg = roll;
                // A boat heading 40 degrees round, heeled 12 and trimmed 5, scaled 2.
                const glm::dmat4 object = glm::translate(glm::dmat4(1.0), glm::dvec3(100.0, 0.7, -40.0)) *
                                          glm::rotate(glm::dmat4(1.0), glm::radians(40.0), glm::dvec3(0, 1, 0)) *
                                          glm::rotate(glm::dmat4(1.0), glm::radians(12.0), glm::dvec3(0, 0, 1)) *
                                          glm::rotate(glm::dmat4(1.0), glm::radians(5.0), glm::dvec3(1, 0, 0)) *
                                          glm::scale(glm::dmat4(1.0), glm::dvec3(2.0));
                const glm::dmat3 turn = glm::dmat3(object) / 2.0;
                const swell::Camera world = swell::mountedCamera(relative, object);
                SCOPED_TRACE(::testing::Message() << "yaw " << yaw << " pitch " << pitch << " roll " << roll);
                const glm::dvec3 at = glm::dvec3(object[3]) + turn * relative.position_m;
                EXPECT_NEAR(glm::distance(world.position_m, at), 0.0, 1e-9);
                EXPECT_NEAR(glm::distance(forwardOf(world), turn * forwardOf(relative)), 0.0, 1e-9);
                EXPECT_NEAR(glm::distance(upOf(world), turn * upOf(relative)), 0.0, 1e-9);
            }
}

TEST(CameraMount, AnUnturnedObjectLeavesTheAnglesAsTheyAre)
{
    swell::Camera relative;
    relative.yaw_deg = 30.0;
    relative.pitch_deg = -8.0;
    relative.roll_deg = 10.0;
    relative.position_m = glm::dvec3(1.0, 2.0, 3.0);
    const swell::Camera world = swell::mountedCamera(relative, glm::translate(glm::dmat4(1.0), glm::dvec3(5.0, 0.0, 0.0)));
    EXPECT_NEAR(world.yaw_deg, 30.0, 1e-9);
    EXPECT_NEAR(world.pitch_deg, -8.0, 1e-9);
    EXPECT_NEAR(world.roll_deg, 10.0, 1e-9);
    EXPECT_NEAR(glm::distance(world.position_m, glm::dvec3(6.0, 2.0, 3.0)), 0.0, 1e-12);
}

} // namespace
