// Each object's pose in the labels (swell/dataset/labels.h ObjectPose,
// docs/LABELS.md "objects"; issue 46, item 4): the model's triangles placed
// by the pose rebuilt from the written position, angles and scale, and
// projected with the written calibration, cover the object's instance mask
// (IoU >= 0.98, the bound). A boat that floats (tilted half way
// towards the waves' normal, so its pitch and roll are not zero), held 4 m
// up so that no water hides its hull.
#include "support/gl_test.h"

#include "assets/mesh_data.h"
#include "support/open_sea.h"
#include "support/projected_mask.h"
#include "swell/dataset/labels.h"
#include "swell/renderer.h"
#include "swell/scene/scene.h"

#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace {

class ObjectPose : public swell::test::GlTest {};

TEST_F(ObjectPose, TheWrittenPoseReprojectsTheModelOntoItsMask)
{
    swell::Scene scene = swell::test::openSea();
    swell::SceneObject boat;
    boat.path = "builtin:boat";
    boat.floats = true; // on the surface, tilted with it (not a rigid body)
    boat.position_m = glm::dvec3(1.5, 4.0, -16.0);
    boat.yaw_deg = 35.0;
    boat.scale = 1.2;
    scene.objects.push_back(boat);
    swell::Renderer renderer(scene);
    swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    camera.position_m = glm::dvec3(0.0, 7.0, 0.0);
    camera.yaw_deg = 0.0;
    camera.pitch_deg = -10.0;
    camera.roll_deg = 4.0;
    const glm::ivec2 size(320, 240);
    renderer.renderImage(camera, 3.0, size);
    const swell::FrameLabels labels = renderer.renderLabels(camera, size);
    ASSERT_EQ(labels.objects.size(), 1u);
    const swell::ObjectLabel& o = labels.objects[0];
    const swell::ObjectPose& pose = o.pose;
    EXPECT_GT(std::abs(pose.pitch_deg) + std::abs(pose.roll_deg), 0.2) << "the sea does not tilt the boat";
    EXPECT_NEAR(pose.scale, 1.2, 1e-9);
    EXPECT_NEAR(std::remainder(pose.heading_deg - (90.0 - pose.yaw_deg), 360.0), 0.0, 2.0); // nearly level
    // The pose from its written parts is the matrix written, and the one drawn.
    const glm::dmat4 rebuilt = swell::worldFromObjectOf(pose.position_m, pose.yaw_deg, pose.pitch_deg, pose.roll_deg, pose.scale);
    const glm::dmat4 drawn = renderer.objectTransforms().at(0);
    for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 4; ++row) {
            EXPECT_NEAR(rebuilt[col][row], pose.worldFromObject[col][row], 1e-9) << col << ", " << row;
            EXPECT_NEAR(drawn[col][row], pose.worldFromObject[col][row], 1e-9) << col << ", " << row;
        }

    const std::vector<bool> projected = swell::test::projectedMask(swell::detail::makeBuiltinModel("boat"), rebuilt, labels.camera);
    long long both = 0, either = 0, mask = 0;
    for (std::size_t i = 0; i < projected.size(); ++i) {
        const bool labelled = labels.instance[i] == o.instance;
        mask += labelled;
        both += labelled && projected[i];
        either += labelled || projected[i];
    }
    ASSERT_GT(mask, 2000) << "the boat is too small in the frame to measure";
    const double iou = double(both) / double(either);
    EXPECT_GE(iou, 0.98) << both << " pixels in both, " << either << " in either, " << mask << " in the mask";
    std::printf("pose: yaw %.3f, pitch %.3f, roll %.3f, heading %.3f deg; IoU %.4f over %lld mask pixels\n",
                pose.yaw_deg, pose.pitch_deg, pose.roll_deg, pose.heading_deg, iou, mask);
}

} // namespace
