// How much of each object shows (swell/dataset/labels.h ObjectLabel's
// occlusion, truncation and amodalPixels, FrameLabels::amodal; docs/LABELS.md
// "objects"; issue 46, item 4): the amodal mask of a boat partly behind
// another is the boat's instance mask in the same frame rendered without the
// other boat, pixel for pixel, and holds its visible mask; its occlusion is
// the share of that render the frame hides. A boat half out of the image
// has the truncation of its mesh's projection over a canvas three images
// wide and high, rasterised on the CPU, within 0.01 (the mesh reprojects
// onto the drawn mask with an IoU of 1.000 in ObjectPose's test, so the two
// outlines differ by a few pixels of the thousands counted).
#include "support/gl_test.h"

#include "assets/mesh_data.h"
#include "support/open_sea.h"
#include "support/projected_mask.h"
#include "swell/dataset/labels.h"
#include "swell/dataset/sensor.h"
#include "swell/renderer.h"
#include "swell/scene/scene.h"

#include <cstdio>
#include <vector>

namespace {

class ObjectVisibility : public swell::test::GlTest {};

swell::SceneObject boatAt(glm::dvec3 position_m, double yaw_deg)
{
    swell::SceneObject boat;
    boat.path = "builtin:boat";
    boat.position_m = position_m;
    boat.yaw_deg = yaw_deg;
    return boat;
}

swell::FrameLabels labelsOf(const swell::Scene& scene, const swell::Camera& camera, glm::ivec2 size)
{
    swell::Renderer renderer(scene);
    renderer.renderImage(camera, 2.0, size);
    return renderer.renderLabels(camera, size);
}

TEST_F(ObjectVisibility, AnOccludedBoatsAmodalMaskIsItsRenderAlone)
{
    swell::Scene scene = swell::test::openSea();
    scene.objects = {boatAt({0.0, 0.0, -24.0}, 0.0), boatAt({2.0, 0.0, -14.0}, 20.0)};
    swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    camera.position_m = glm::dvec3(0.0, 3.0, 0.0);
    camera.yaw_deg = 0.0;
    camera.pitch_deg = -4.0;
    const glm::ivec2 size(240, 180);
    const swell::FrameLabels both = labelsOf(scene, camera, size);
    swell::Scene aloneScene = scene;
    aloneScene.objects.pop_back();
    const swell::FrameLabels alone = labelsOf(aloneScene, camera, size);

    ASSERT_EQ(both.objects.size(), 2u);
    ASSERT_EQ(both.amodal.size(), 2u * std::size_t(size.x) * std::size_t(size.y));
    const swell::ObjectLabel& far = both.objects[0];
    long long aloneMask = 0, differ = 0, visibleOutside = 0;
    for (std::size_t i = 0; i < both.instance.size(); ++i) {
        const bool amodal = both.amodal[i] != 0;
        const bool rendered = alone.instance[i] == far.instance;
        aloneMask += rendered;
        differ += amodal != rendered;
        visibleOutside += both.instance[i] == far.instance && !amodal;
    }
    EXPECT_EQ(differ, 0) << "pixels where the amodal mask and the render of the boat alone differ";
    EXPECT_EQ(visibleOutside, 0) << "visible pixels outside the amodal mask";
    EXPECT_EQ(far.amodalPixels, aloneMask);
    const double hidden = 1.0 - double(far.visiblePixels) / double(aloneMask);
    EXPECT_NEAR(far.occlusion, hidden, 1e-12);
    EXPECT_GT(far.occlusion, 0.1) << "the near boat hides too little of the far one to measure";
    EXPECT_LT(far.occlusion, 0.9);
    EXPECT_EQ(far.truncation, 0.0);
    // The near boat: nothing in front of it, all of it in the image.
    EXPECT_EQ(both.objects[1].occlusion, 0.0);
    EXPECT_EQ(both.objects[1].amodalPixels, both.objects[1].visiblePixels);
    std::printf("far boat: %lld visible of %lld alone, occlusion %.4f; boxes %d %d %d %d and %d %d %d %d\n",
                far.visiblePixels, aloneMask, far.occlusion, far.box_px.x, far.box_px.y, far.box_px.z, far.box_px.w,
                both.objects[1].box_px.x, both.objects[1].box_px.y, both.objects[1].box_px.z, both.objects[1].box_px.w);
}

TEST_F(ObjectVisibility, ABoatHalfOutOfTheImageHasItsMeshsTruncation)
{
    swell::Scene scene = swell::test::openSea();
    scene.objects = {boatAt({0.0, 4.0, -12.0}, 10.0)}; // 4 m up: no water hides its hull
    swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    camera.position_m = glm::dvec3(8.5, 5.0, 0.0); // the boat's middle near the image's left border
    camera.yaw_deg = 0.0;
    camera.pitch_deg = -3.0;
    const glm::ivec2 size(320, 240);
    const swell::FrameLabels labels = labelsOf(scene, camera, size);
    ASSERT_EQ(labels.objects.size(), 1u);
    const swell::ObjectLabel& o = labels.objects[0];

    // The mesh over a canvas three times as wide and high, the image its middle block.
    swell::CameraCalibration canvas = labels.camera;
    canvas.size = 3 * size;
    canvas.cx_px += size.x;
    canvas.cy_px += size.y;
    const std::vector<bool> mesh =
        swell::test::projectedMask(swell::detail::makeBuiltinModel("boat"), o.pose.worldFromObject, canvas);
    long long total = 0, inside = 0;
    for (int y = 0; y < canvas.size.y; ++y)
        for (int x = 0; x < canvas.size.x; ++x)
            if (mesh[std::size_t(y) * std::size_t(canvas.size.x) + std::size_t(x)]) {
                ++total;
                inside += x >= size.x && x < 2 * size.x && y >= size.y && y < 2 * size.y;
            }
    ASSERT_GT(total, 1000) << "the boat is too small to measure";
    const double truncated = 1.0 - double(inside) / double(total);
    EXPECT_GT(truncated, 0.2) << "the boat is not half out of the image";
    EXPECT_LT(truncated, 0.8);
    EXPECT_NEAR(o.truncation, truncated, 0.01);
    EXPECT_EQ(o.occlusion, 0.0);
    EXPECT_EQ(o.amodalPixels, o.visiblePixels);
    std::printf("truncation %.4f, the mesh's %.4f (%lld of %lld pixels inside)\n", o.truncation, truncated, inside, total);
}

// Through a lens (renderSensorFrame): the masks are resampled as the
// instance image is, so the amodal mask still holds the visible pixels, and
// the truncation is the share of the silhouette whose rays the distorted
// image does not show: against the mesh rasterised on the CPU over a
// pinhole canvas three images wide and high at the output's focal length,
// each covered pixel's ray put through the lens, within 0.02 (the label
// pass's pinhole frame samples the silhouette 1.5 times as finely).
TEST_F(ObjectVisibility, ThroughALensTheTruncationIsOfTheRaysTheImageShows)
{
    swell::Scene scene = swell::test::openSea();
    scene.objects = {boatAt({0.0, 4.0, -12.0}, 10.0)};
    scene.camera.fovY_deg = 50.0;
    scene.camera.distortionK1 = -0.15;
    swell::Renderer renderer(scene);
    swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    camera.position_m = glm::dvec3(7.5, 5.0, 0.0);
    camera.yaw_deg = 0.0;
    camera.pitch_deg = -3.0;
    const glm::ivec2 size(320, 240);
    const swell::SensorFrame frame = swell::renderSensorFrame(renderer, camera, 2.0, size, true);
    ASSERT_TRUE(frame.labels.has_value());
    const swell::FrameLabels& labels = *frame.labels;
    ASSERT_EQ(labels.objects.size(), 1u);
    const swell::ObjectLabel& o = labels.objects[0];
    long long visibleOutside = 0;
    for (std::size_t i = 0; i < labels.instance.size(); ++i)
        visibleOutside += labels.instance[i] == o.instance && labels.amodal[i] == 0;
    EXPECT_EQ(visibleOutside, 0) << "visible pixels outside the amodal mask";
    EXPECT_GT(o.amodalPixels, 500);

    swell::CameraCalibration canvas = labels.camera;
    canvas.k1 = canvas.k2 = canvas.k3 = canvas.p1 = canvas.p2 = 0.0;
    canvas.size = 3 * size;
    canvas.cx_px += size.x;
    canvas.cy_px += size.y;
    const std::vector<bool> mesh =
        swell::test::projectedMask(swell::detail::makeBuiltinModel("boat"), o.pose.worldFromObject, canvas);
    const swell::LensDistortion lens{labels.camera.k1, labels.camera.k2, labels.camera.k3, labels.camera.p1,
                                     labels.camera.p2};
    long long total = 0, shown = 0;
    for (int y = 0; y < canvas.size.y; ++y)
        for (int x = 0; x < canvas.size.x; ++x) {
            if (!mesh[std::size_t(y) * std::size_t(canvas.size.x) + std::size_t(x)])
                continue;
            ++total;
            const glm::dvec2 u((x + 0.5 - canvas.cx_px) / canvas.fx_px, (y + 0.5 - canvas.cy_px) / canvas.fy_px);
            if (!swell::insideFold(lens, u))
                continue;
            const glm::dvec2 d = swell::distort(lens, u);
            const double px = labels.camera.fx_px * d.x + labels.camera.cx_px,
                         py = labels.camera.fy_px * d.y + labels.camera.cy_px;
            shown += px >= 0.0 && py >= 0.0 && px < size.x && py < size.y;
        }
    ASSERT_GT(total, 1000);
    const double truncated = 1.0 - double(shown) / double(total);
    EXPECT_GT(truncated, 0.2) << "the boat is not partly out of the image";
    EXPECT_LT(truncated, 0.8);
    EXPECT_NEAR(o.truncation, truncated, 0.02);
    std::printf("through the lens: truncation %.4f, the mesh's %.4f\n", o.truncation, truncated);
}

} // namespace
