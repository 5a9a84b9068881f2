// Frames through Kannala-Brandt's fisheye (camera.lens = "kannala_brandt";
// docs/SCENE.md "The lens", docs/LABELS.md "Cameras as sensors"): each
// pixel's labels lie along the ray that the written calibration gives its
// centre by the published equations (Kannala & Brandt 2006, eq. 6, in
// OpenCV's cv2.fisheye form), written out here apart from the library's;
// the widest field drawn shows the horizon where those equations put it;
// the optical flow projects through the fisheye.
#include "support/gl_test.h"

#include "assets/mesh_data.h"
#include "support/mesh_ray_cast.h"
#include "support/open_sea.h"
#include "swell/dataset/flow.h"
#include "swell/dataset/labels.h"
#include "swell/dataset/sensor.h"
#include "swell/flat_model.h"
#include "swell/gpu/label_classes.h"
#include "swell/renderer.h"
#include "swell/scene/scene.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <vector>

namespace {

class FisheyeFrames : public swell::test::GlTest {};

double thetaD(const swell::CameraCalibration& c, double theta)
{
    const double t2 = theta * theta;
    return theta * (1.0 + c.k1 * t2 + c.k2 * t2 * t2 + c.k3 * t2 * t2 * t2 + c.k4 * t2 * t2 * t2 * t2);
}

// The published model's unit ray (camera axes) through image point p: theta
// from theta_d by bisection (theta_d grows with theta over the field).
glm::dvec3 cameraRay(const swell::CameraCalibration& c, glm::dvec2 p)
{
    const glm::dvec2 d((p.x - c.cx_px) / c.fx_px, (p.y - c.cy_px) / c.fy_px);
    const double target = glm::length(d);
    if (target == 0.0)
        return {0.0, 0.0, 1.0};
    double lo = 0.0, hi = 0.5 * std::numbers::pi;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (thetaD(c, mid) < target ? lo : hi) = mid;
    }
    const double theta = 0.5 * (lo + hi);
    return {std::sin(theta) * d.x / target, std::sin(theta) * d.y / target, std::cos(theta)};
}

glm::dvec3 worldRay(const swell::CameraCalibration& c, glm::dvec2 p)
{
    return glm::normalize(glm::dmat3(c.worldFromCamera) * cameraRay(c, p));
}

// The published model's pixel of a world point: theta = atan2(|(x, y)|, z).
glm::dvec2 pixelOf(const swell::CameraCalibration& c, glm::dvec3 world_m)
{
    const glm::dvec3 p(c.cameraFromWorld * glm::dvec4(world_m, 1.0));
    const double r = std::hypot(p.x, p.y), theta = std::atan2(r, p.z);
    return {c.fx_px * thetaD(c, theta) * p.x / r + c.cx_px, c.fy_px * thetaD(c, theta) * p.y / r + c.cy_px};
}

double fisheyeFramesQuantile(std::vector<double> v, double q)
{
    if (v.empty())
        return 0.0;
    std::sort(v.begin(), v.end());
    return v[std::size_t(q * double(v.size() - 1))];
}

swell::Scene fisheyeSea(double fovY_deg)
{
    swell::Scene scene = swell::test::openSea();
    scene.camera.lens = swell::LensModel::KannalaBrandt;
    scene.camera.fovY_deg = fovY_deg;
    return scene;
}

// On calm water, the point each water pixel's range labels (on the sea's
// plane, in its centre ray's bearing) projects by the published equations
// within 0.1 px of that pixel's centre; the water and the sky lie on their
// sides of the horizon those equations give; on a buoy, the range is where
// the equations' centre ray meets its mesh.
TEST_F(FisheyeFrames, EachPixelsLabelsLieAlongTheRayThePublishedEquationsGiveIt)
{
    swell::Scene scene = fisheyeSea(80.0);
    scene.camera.fisheyeK1 = 0.03;
    scene.camera.fisheyeK2 = -0.01;
    scene.camera.fisheyeK3 = 0.002;
    scene.camera.fisheyeK4 = -0.0005;
    swell::SceneObject buoy;
    buoy.path = "builtin:buoy";
    buoy.position_m = glm::dvec3(1.0, 0.0, -6.0);
    scene.objects.push_back(buoy);
    swell::Renderer renderer(scene);
    renderer.setWaveModel(std::make_shared<swell::FlatModel>());
    swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    const double height_m = 3.0;
    camera.position_m = glm::dvec3(0.0, height_m, 0.0);
    camera.yaw_deg = 0.0;
    camera.pitch_deg = -16.0;
    camera.roll_deg = 6.0;
    const glm::ivec2 size(200, 150);
    const swell::SensorFrame frame = swell::renderSensorFrame(renderer, camera, 0.0, size, true);
    ASSERT_TRUE(frame.labels);
    const swell::FrameLabels& labels = *frame.labels;
    const swell::CameraCalibration& c = labels.camera;
    // The calibration written: the model, its coefficients, and the focal
    // length that puts the field's borders 40 degrees from the axis.
    ASSERT_EQ(c.lensModel, swell::LensModel::KannalaBrandt);
    EXPECT_EQ(c.k1, 0.03);
    EXPECT_EQ(c.k4, -0.0005);
    EXPECT_NEAR(c.fy_px, 75.0 / thetaD(c, glm::radians(40.0)), 1e-9);

    const swell::detail::MeshData mesh = swell::detail::makeBuiltinModel("buoy");
    const glm::dmat4 pose = renderer.objectTransforms().at(0);
    const glm::dvec3 eye = camera.position_m;
    std::vector<double> waterOff_px, buoyErrors_m;
    int wrongSide = 0, farOff = 0, buoyOff = 0;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(size.x) + std::size_t(x);
            const glm::dvec2 centre(x + 0.5, y + 0.5);
            const glm::dvec3 d = worldRay(c, centre);
            const std::uint16_t s = labels.semantic[i];
            if (labels.instance[i] == 0) {
                const bool below = d.y < 0.0;
                bool nearHorizon = false;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx)
                        nearHorizon = nearHorizon || (worldRay(c, centre + glm::dvec2(dx, dy)).y < 0.0) != below;
                if (!nearHorizon && (s == SWELL_LABEL_WATER) != below)
                    ++wrongSide;
            }
            if (s == SWELL_LABEL_WATER && labels.instance[i] == 0 && d.y < -std::sin(glm::radians(0.5))) {
                // The labelled point: on the sea's plane, range_m from the
                // eye, in the bearing of the centre ray.
                const double range_m = labels.range_m[i];
                const double across_m = std::sqrt(std::max(range_m * range_m - height_m * height_m, 0.0));
                const glm::dvec3 bearing = glm::normalize(glm::dvec3(d.x, 0.0, d.z));
                const glm::dvec3 point = glm::dvec3(eye.x, 0.0, eye.z) + across_m * bearing;
                waterOff_px.push_back(glm::distance(pixelOf(c, point), centre));
                farOff += waterOff_px.back() > 0.1;
            } else if (labels.instance[i] == 1) {
                const double expected_m = swell::test::rayCastMesh(mesh, pose, eye, d);
                if (!std::isfinite(expected_m))
                    continue; // the centre ray grazes past the silhouette
                buoyErrors_m.push_back(std::abs(double(labels.range_m[i]) - expected_m));
                buoyOff += buoyErrors_m.back() > 0.01;
            }
        }
    EXPECT_EQ(wrongSide, 0);
    EXPECT_GT(waterOff_px.size(), std::size_t(size.x * size.y / 3));
    EXPECT_EQ(farOff, 0) << "water pixels' points: median " << fisheyeFramesQuantile(waterOff_px, 0.5) << " px, 99th percentile "
                         << fisheyeFramesQuantile(waterOff_px, 0.99) << " px, worst " << fisheyeFramesQuantile(waterOff_px, 1.0) << " px";
    EXPECT_GT(buoyErrors_m.size(), 100u);
    EXPECT_LE(fisheyeFramesQuantile(buoyErrors_m, 0.5), 0.001);
    EXPECT_LE(buoyOff, int(buoyErrors_m.size()) / 10) << "median " << fisheyeFramesQuantile(buoyErrors_m, 0.5) << " m";
    // The buoy's box is measured on the fisheye's mask: it holds every buoy pixel.
    ASSERT_EQ(labels.objects.size(), 1u);
    EXPECT_GT(labels.objects[0].visiblePixels, 100);
    std::printf("fisheye: water points worst %.3g px (median %.3g) over %zu pixels; buoy median %.3g m over %zu\n",
                fisheyeFramesQuantile(waterOff_px, 1.0), fisheyeFramesQuantile(waterOff_px, 0.5), waterOff_px.size(),
                fisheyeFramesQuantile(buoyErrors_m, 0.5), buoyErrors_m.size());
}

// The widest field the fisheye draws at 160x120: an equidistant fisheye
// (theta_d = theta) at 88 degrees of vertical field, 146.7 across the
// diagonal (89 is refused), pitched and rolled: every pixel whose neighbours' rays lie on
// one side of the horizon by the published equations is sky above it and
// water below, and the horizon's curve_px points lie on it.
TEST_F(FisheyeFrames, TheWidestFieldShowsTheHorizonWhereTheEquationsPutIt)
{
    const swell::Scene scene = fisheyeSea(88.0);
    EXPECT_NE(swell::lensProblem(swell::lensOf(fisheyeSea(89.0).camera), 89.0, {160, 120}), "");
    swell::Renderer renderer(scene);
    renderer.setWaveModel(std::make_shared<swell::FlatModel>());
    swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    camera.position_m = glm::dvec3(0.0, 10.0, 0.0);
    camera.pitch_deg = -25.0;
    camera.roll_deg = 12.0;
    const glm::ivec2 size(160, 120);
    const swell::SensorFrame frame = swell::renderSensorFrame(renderer, camera, 0.0, size, true);
    ASSERT_TRUE(frame.labels);
    const swell::FrameLabels& labels = *frame.labels;
    const swell::CameraCalibration& c = labels.camera;
    // The corners' rays: 146.7 degrees apart across the diagonal (88 times
    // the half-diagonal over the half-height, 100 / 60).
    EXPECT_NEAR(2.0 * glm::degrees(std::acos(cameraRay(c, {0.0, 0.0}).z)), 88.0 * 100.0 / 60.0, 1e-9);
    int wrongSide = 0, sky = 0, water = 0;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(size.x) + std::size_t(x);
            const glm::dvec2 centre(x + 0.5, y + 0.5);
            const bool below = worldRay(c, centre).y < 0.0;
            bool nearHorizon = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    nearHorizon = nearHorizon || (worldRay(c, centre + glm::dvec2(dx, dy)).y < 0.0) != below;
            if (nearHorizon)
                continue;
            const std::uint16_t s = labels.semantic[i];
            sky += s == SWELL_LABEL_SKY;
            water += s == SWELL_LABEL_WATER;
            wrongSide += below ? s != SWELL_LABEL_WATER : s != SWELL_LABEL_SKY;
        }
    EXPECT_EQ(wrongSide, 0);
    EXPECT_GT(sky, 2000);
    EXPECT_GT(water, 2000);
    EXPECT_GT(labels.horizon.curve_px.size(), 30u);
    double worst_deg = 0.0;
    for (const glm::dvec2& p : labels.horizon.curve_px)
        worst_deg = std::max(worst_deg, std::abs(glm::degrees(std::asin(worldRay(c, p).y))));
    EXPECT_LT(worst_deg, 1e-6);
}

// The optical flow projects through the fisheye: each calm water pixel's
// flow is where the sea's plane, met by its centre ray, lands by the
// published equations through the moved camera's calibration.
TEST_F(FisheyeFrames, TheOpticalFlowProjectsThroughTheFisheye)
{
    swell::Scene scene = fisheyeSea(80.0);
    scene.camera.fisheyeK1 = -0.02;
    scene.camera.fisheyeK2 = 0.004;
    swell::Renderer renderer(scene);
    renderer.setWaveModel(std::make_shared<swell::FlatModel>());
    swell::Camera before = swell::cameraAt(scene.camera, 0.0);
    before.position_m = glm::dvec3(0.0, 4.0, 0.0);
    before.yaw_deg = 0.0;
    before.pitch_deg = -15.0;
    before.roll_deg = 5.0;
    swell::Camera after = before;
    after.position_m += glm::dvec3(-0.3, 0.1, -0.5);
    after.yaw_deg += 0.8;
    const glm::ivec2 size(160, 120);
    const double interval_s = 0.1;
    const swell::SensorFrame first = swell::renderSensorFrame(renderer, before, 1.0, size, true);
    const swell::SensorFrame second = swell::renderSensorFrame(renderer, after, 1.0 + interval_s, size, true);
    ASSERT_TRUE(first.labels && second.labels);
    const swell::FrameFlow flow = swell::opticalFlowOf(*first.labels, 1.0, *second.labels, interval_s,
                                                       swell::seaMotionOf(scene, renderer.waveModel()));
    const swell::CameraCalibration& c0 = first.labels->camera;
    ASSERT_EQ(second.labels->camera.lensModel, swell::LensModel::KannalaBrandt);
    const glm::dvec3 eye(c0.worldFromCamera[3]);
    double worst_px = 0.0, largest_px = 0.0;
    int water = 0;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(size.x) + std::size_t(x);
            if (first.labels->semantic[i] != SWELL_LABEL_WATER || !flow.valid[i])
                continue;
            const glm::dvec2 centre(x + 0.5, y + 0.5);
            const glm::dvec3 d = worldRay(c0, centre);
            if (d.y > -0.01)
                continue; // near the horizon: where the plane's point is kilometres off
            const glm::dvec3 point = eye + (-eye.y / d.y) * d;
            const glm::dvec2 expected = pixelOf(second.labels->camera, point) - centre;
            worst_px = std::max(worst_px, glm::length(glm::dvec2(flow.flow_px[i]) - expected));
            largest_px = std::max(largest_px, glm::length(expected));
            water += 1;
        }
    EXPECT_GT(water, size.x * size.y / 3);
    EXPECT_GT(largest_px, 2.0);
    EXPECT_LT(worst_px, 0.05) << "over " << water << " water pixels";
    std::printf("fisheye flow: worst %.3g px over %d water pixels (largest motion %.2f px)\n", worst_px, water,
                largest_px);
}

} // namespace
