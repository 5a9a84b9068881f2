// Forward optical flow (swell/dataset/flow.h, docs/LABELS.md "Optical flow";
// issue 46, item 2), held to what it should be from outside its own
// arithmetic: on a still scene with a camera that moves, the analytic
// projection of each pixel's point (the sea's plane met by its centre ray,
// a fixed buoy's mesh met by a CPU ray cast) into the moved camera; on a
// floating body, its mesh's points (a CPU ray cast at the first time) moved
// by its pose at the second; and on a wind sea, the colour frame at t + dt
// warped back by the flow against the frame at t.
#include "support/gl_test.h"

#include "assets/mesh_data.h"
#include "support/mesh_ray_cast.h"
#include "support/open_sea.h"
#include "swell/dataset/flow.h"
#include "swell/drawn_surface.h"
#include "swell/dataset/labels.h"
#include "swell/dataset/sensor.h"
#include "swell/flat_model.h"
#include "swell/gpu/label_classes.h"
#include "swell/renderer.h"
#include "swell/scene/grid.h"
#include "swell/scene/scene.h"
#include "swell/scene/scene_file.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <vector>

namespace {

class OpticalFlow : public swell::test::GlTest {};

struct LabelledFrame {
    swell::Image image;
    swell::FrameLabels labels;
};

LabelledFrame drawFrame(swell::Renderer& renderer, const swell::Camera& camera, double time_s, glm::ivec2 size)
{
    LabelledFrame f;
    f.image = renderer.renderImage(camera, time_s, size);
    f.labels = renderer.renderLabels(camera, size);
    return f;
}

// The world ray through pixel (x, y)'s centre of a pinhole calibration.
glm::dvec3 opticalFlowCentreRay(const swell::CameraCalibration& c, int x, int y)
{
    const glm::dvec3 v((x + 0.5 - c.cx_px) / c.fx_px, (y + 0.5 - c.cy_px) / c.fy_px, 1.0);
    return glm::normalize(glm::dmat3(c.worldFromCamera) * v);
}

// A pinhole projection written out: K (R X + t).
glm::dvec2 pinholeProject(const swell::CameraCalibration& c, glm::dvec3 world_m)
{
    const glm::dvec3 p(c.cameraFromWorld * glm::dvec4(world_m, 1.0));
    return {c.fx_px * p.x / p.z + c.cx_px, c.fy_px * p.y / p.z + c.cy_px};
}

glm::dvec2 flowAt(const swell::FrameFlow& flow, std::size_t i) { return glm::dvec2(flow.flow_px[i]); }

// The scene's camera at position_m, looking north (-z), pitched and rolled.
swell::Camera cameraLookingNorth(const swell::Scene& scene, glm::dvec3 position_m, double pitch_deg, double roll_deg = 0.0)
{
    swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    camera.position_m = position_m;
    camera.yaw_deg = 0.0;
    camera.pitch_deg = pitch_deg;
    camera.roll_deg = roll_deg;
    return camera;
}

// The built-in boat as a floating rigid body (it heaves, rolls and pitches)
// under way at velocity_mps.
swell::SceneObject boatUnderWay(glm::dvec3 position_m, double yaw_deg, glm::dvec3 velocity_mps)
{
    swell::SceneObject boat;
    boat.path = "builtin:boat";
    boat.position_m = position_m;
    boat.yaw_deg = yaw_deg;
    boat.floats = true;
    boat.density_kg_per_m3 = 400.0;
    boat.velocity_m_per_s = velocity_mps;
    return boat;
}

TEST_F(OpticalFlow, OnAStillSceneItIsTheProjectionOfTheCamerasMotion)
{
    swell::Scene scene = swell::test::openSea();
    swell::SceneObject buoy;
    buoy.path = "builtin:buoy";
    buoy.position_m = glm::dvec3(1.5, 0.0, -12.0); // fixed: it does not float
    scene.objects.push_back(buoy);
    swell::Renderer renderer(scene);
    renderer.setWaveModel(std::make_shared<swell::FlatModel>());
    const swell::Camera before = cameraLookingNorth(scene, glm::dvec3(0.0, 3.0, 0.0), -12.0, 3.0);
    swell::Camera after = before;
    after.position_m += glm::dvec3(0.4, 0.15, -0.6); // a translation alone
    const glm::ivec2 size(240, 180);
    const double interval_s = 0.1;
    const LabelledFrame first = drawFrame(renderer, before, 1.0, size);
    const LabelledFrame second = drawFrame(renderer, after, 1.0 + interval_s, size);
    const swell::FrameFlow flow = swell::opticalFlowOf(first.labels, 1.0, second.labels, interval_s,
                                                       swell::seaMotionOf(scene, renderer.waveModel()));
    ASSERT_EQ(flow.size, size);

    const swell::CameraCalibration& c0 = first.labels.camera;
    const swell::CameraCalibration& c1 = second.labels.camera;
    const glm::dvec3 eye(c0.worldFromCamera[3]);
    const swell::detail::MeshData mesh = swell::detail::makeBuiltinModel("buoy");
    const glm::dmat4 pose = renderer.objectTransforms().at(0);
    double worstWater_px = 0.0, worstBuoy_px = 0.0;
    int water = 0, onBuoy = 0, sky = 0, hidden = 0;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(size.x) + std::size_t(x);
            const glm::dvec3 d = opticalFlowCentreRay(c0, x, y);
            // Where the moved camera sees a world point, less this pixel's centre.
            auto projectedMotion = [&](glm::dvec3 point) { return pinholeProject(c1, point) - glm::dvec2(x + 0.5, y + 0.5); };
            const std::uint16_t semantic = first.labels.semantic[i];
            if (semantic == SWELL_LABEL_SKY) {
                sky += 1;
                EXPECT_EQ(flow.valid[i], 0) << "the sky has no point to follow";
                continue;
            }
            if (semantic == SWELL_LABEL_WATER && d.y < 0.0) {
                // Water that lands where the second frame shows the buoy
                // all round is behind it there: hidden.
                const glm::dvec2 lands = pinholeProject(c1, eye + (-eye.y / d.y) * d);
                const glm::ivec2 at(glm::floor(lands - 0.5));
                bool buoyAllRound = at.x >= 0 && at.y >= 0 && at.x + 1 < size.x && at.y + 1 < size.y;
                for (int k = 0; k < 4 && buoyAllRound; ++k)
                    buoyAllRound = second.labels.instance[std::size_t(at.y + k / 2) * std::size_t(size.x) +
                                                          std::size_t(at.x + k % 2)] == 1;
                if (buoyAllRound) {
                    hidden += 1;
                    EXPECT_EQ(flow.valid[i], 0) << "water behind the buoy at (" << x << ", " << y << ")";
                }
            }
            if (!flow.valid[i])
                continue;
            glm::dvec3 point;
            if (semantic == SWELL_LABEL_WATER && d.y < 0.0) {
                point = eye + (-eye.y / d.y) * d; // the sea level's plane, y = 0
                const double error_px = glm::length(flowAt(flow, i) - projectedMotion(point));
                worstWater_px = std::max(worstWater_px, error_px);
                water += 1;
            } else if (first.labels.instance[i] == 1) {
                const std::optional<swell::test::MeshHit> hit = swell::test::rayHitOnMesh(mesh, pose, eye, d);
                if (!hit || std::abs(hit->distance_m - first.labels.range_m[i]) > 0.01)
                    continue; // the centre ray grazes the outline, or the label's range is a crease's
                point = eye + hit->distance_m * d;
                const double error_px = glm::length(flowAt(flow, i) - projectedMotion(point));
                worstBuoy_px = std::max(worstBuoy_px, error_px);
                onBuoy += 1;
            }
        }
    EXPECT_GT(water, size.x * size.y / 3);
    EXPECT_GT(onBuoy, 150);
    EXPECT_GT(sky, 1000);
    EXPECT_GT(hidden, 20) << "the camera's move hides no water behind the buoy: occlusion not measured";
    EXPECT_LT(worstWater_px, 0.05) << "over " << water << " water pixels";
    EXPECT_LT(worstBuoy_px, 0.05) << "over " << onBuoy << " buoy pixels";
    std::printf("still scene: worst %.5f px on %d water pixels, %.5f px on %d buoy pixels; %d hidden\n",
                worstWater_px, water, worstBuoy_px, onBuoy, hidden);
}

// Brown-Conrady's distortion as LABELS.md writes it (OpenCV's form), for the
// calibration's coefficients, and the pixel it puts a world point on.
glm::dvec2 projectThroughLens(const swell::CameraCalibration& c, glm::dvec3 world_m)
{
    const glm::dvec3 p(c.cameraFromWorld * glm::dvec4(world_m, 1.0));
    const double x = p.x / p.z, y = p.y / p.z, r2 = x * x + y * y;
    const double radial = 1.0 + c.k1 * r2 + c.k2 * r2 * r2 + c.k3 * r2 * r2 * r2;
    const double xd = x * radial + 2.0 * c.p1 * x * y + c.p2 * (r2 + 2.0 * x * x);
    const double yd = y * radial + c.p1 * (r2 + 2.0 * y * y) + 2.0 * c.p2 * x * y;
    return {c.fx_px * xd + c.cx_px, c.fy_px * yd + c.cy_px};
}

// Through a distorting lens (the frames as `swell render` draws them, their
// labels resampled through it): each calm water pixel's flow is where the
// sea's plane, met by its centre ray (undistorted), lands through the lens
// of the moved camera.
TEST_F(OpticalFlow, ThroughALensItIsTheProjectionThroughTheLens)
{
    const swell::Scene scene = swell::test::openSeaThroughALens();
    swell::Renderer renderer(scene);
    renderer.setWaveModel(std::make_shared<swell::FlatModel>());
    const swell::Camera before = cameraLookingNorth(scene, glm::dvec3(0.0, 4.0, 0.0), -15.0, 5.0);
    swell::Camera after = before;
    after.position_m += glm::dvec3(-0.3, 0.1, -0.5);
    after.yaw_deg += 0.8;
    const glm::ivec2 size(240, 180);
    const double interval_s = 0.1;
    const swell::SensorFrame first = swell::renderSensorFrame(renderer, before, 1.0, size, true);
    const swell::SensorFrame second = swell::renderSensorFrame(renderer, after, 1.0 + interval_s, size, true);
    ASSERT_TRUE(first.labels && second.labels);
    const swell::FrameFlow flow = swell::opticalFlowOf(*first.labels, 1.0, *second.labels, interval_s,
                                                       swell::seaMotionOf(scene, renderer.waveModel()));
    const swell::CameraCalibration& c0 = first.labels->camera;
    ASSERT_EQ(c0.k1, -0.22);
    const swell::LensDistortion lens = swell::lensOf(scene.camera);
    const glm::dvec3 eye(c0.worldFromCamera[3]);
    double worst_px = 0.0;
    int water = 0;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(size.x) + std::size_t(x);
            if (first.labels->semantic[i] != SWELL_LABEL_WATER || !flow.valid[i])
                continue;
            const glm::dvec2 u = swell::undistort(lens, {(x + 0.5 - c0.cx_px) / c0.fx_px, (y + 0.5 - c0.cy_px) / c0.fy_px});
            const glm::dvec3 d = glm::normalize(glm::dmat3(c0.worldFromCamera) * glm::dvec3(u, 1.0));
            if (d.y > -0.01)
                continue; // near the horizon: where the plane's point is kilometres off
            const glm::dvec3 point = eye + (-eye.y / d.y) * d;
            const glm::dvec2 expected = projectThroughLens(second.labels->camera, point) - glm::dvec2(x + 0.5, y + 0.5);
            worst_px = std::max(worst_px, glm::length(flowAt(flow, i) - expected));
            water += 1;
        }
    EXPECT_GT(water, size.x * size.y / 3);
    EXPECT_LT(worst_px, 0.05) << "over " << water << " water pixels";
    std::printf("through a lens: worst %.5f px over %d water pixels\n", worst_px, water);
}

TEST_F(OpticalFlow, OnAFloatingBodyItIsTheMotionOfItsMeshsPoints)
{
    swell::Scene scene = swell::test::openSea();
    scene.objects.push_back(boatUnderWay(glm::dvec3(-2.0, 0.0, -18.0), 20.0, glm::dvec3(1.5, 0.0, -0.5)));
    swell::Renderer renderer(scene);
    const swell::Camera camera = cameraLookingNorth(scene, glm::dvec3(0.0, 6.0, 0.0), -12.0);
    const glm::ivec2 size(240, 180);
    const double time_s = 4.0, interval_s = 0.2;
    const LabelledFrame first = drawFrame(renderer, camera, time_s, size);
    const glm::dmat4 poseBefore = renderer.objectTransforms().at(0);
    const LabelledFrame second = drawFrame(renderer, camera, time_s + interval_s, size);
    const glm::dmat4 poseAfter = renderer.objectTransforms().at(0);
    const swell::FrameFlow flow = swell::opticalFlowOf(first.labels, time_s, second.labels, interval_s,
                                                       swell::seaMotionOf(scene, renderer.waveModel()));

    const swell::CameraCalibration& c0 = first.labels.camera;
    const glm::dvec3 eye(c0.worldFromCamera[3]);
    const swell::detail::MeshData mesh = swell::detail::makeBuiltinModel("boat");
    double worst_px = 0.0, largestMotion_px = 0.0;
    int measured = 0;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(size.x) + std::size_t(x);
            if (first.labels.instance[i] != 1)
                continue;
            const glm::dvec3 d = opticalFlowCentreRay(c0, x, y);
            const std::optional<swell::test::MeshHit> hit = swell::test::rayHitOnMesh(mesh, poseBefore, eye, d);
            if (!hit || std::abs(hit->distance_m - first.labels.range_m[i]) > 0.01)
                continue; // the centre ray grazes the outline, or the label's range is a crease's
            // The mesh's point, where the body's pose a frame later puts it.
            const glm::dvec3 moved(poseAfter * glm::dvec4(hit->model_m, 1.0));
            const glm::dvec2 expected = pinholeProject(second.labels.camera, moved) - glm::dvec2(x + 0.5, y + 0.5);
            worst_px = std::max(worst_px, glm::length(flowAt(flow, i) - expected));
            largestMotion_px = std::max(largestMotion_px, glm::length(expected));
            measured += 1;
        }
    EXPECT_GT(measured, 400);
    EXPECT_GT(largestMotion_px, 2.0) << "the boat hardly moves: nothing measured";
    EXPECT_LT(worst_px, 0.1) << "over " << measured << " pixels of the boat";
    std::printf("floating body: worst %.5f px over %d pixels moving up to %.2f px\n", worst_px, measured,
                largestMotion_px);
}

// Where the ray from eye along the unit direction d meets the plane of the
// triangle (a, b, c): the distance and the barycentric weights; empty where
// it runs along it or misses the triangle.
struct TriangleHit {
    double distance_m = 0.0;
    glm::dvec3 weights{0.0};
};
std::optional<TriangleHit> rayHitsTriangle(glm::dvec3 eye, glm::dvec3 d, const glm::dvec3 (&v)[3])
{
    const glm::dvec3 e1 = v[1] - v[0], e2 = v[2] - v[0], p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-15)
        return std::nullopt;
    const glm::dvec3 s0 = eye - v[0], q = glm::cross(s0, e1);
    const double u = glm::dot(s0, p) / det, w = glm::dot(d, q) / det;
    if (u < -1e-9 || w < -1e-9 || u + w > 1.0 + 1e-9)
        return std::nullopt;
    return TriangleHit{glm::dot(e2, q) / det, glm::dvec3(1.0 - u - w, u, w)};
}

// The water's points are the drawn grid's material points: with the camera
// still (the grid does not move), each vertex of the drawn surface
// (Renderer::drawnSurface, the CPU twin of the vertex shader) at t and at
// t + dt is one point of the sea. Each water pixel whose centre ray meets a
// drawn triangle at its labelled range (either diagonal of each cell: the
// one drawn is the one the range lies on) has its point's barycentric
// weights there; the same weights on the triangle's vertices at t + dt,
// projected, are where the flow must send it.
TEST_F(OpticalFlow, OnTheWaterItFollowsTheSeasMaterialPoints)
{
    swell::Scene scene = swell::test::openSea();
    swell::Renderer renderer(scene);
    const swell::Camera camera = cameraLookingNorth(scene, glm::dvec3(0.0, 4.0, 0.0), -20.0);
    const glm::ivec2 size(240, 180);
    const double time_s = 4.0, interval_s = 0.1;
    const LabelledFrame first = drawFrame(renderer, camera, time_s, size);
    const swell::DrawnSurface before = renderer.drawnSurface(camera, time_s);
    const LabelledFrame second = drawFrame(renderer, camera, time_s + interval_s, size);
    const swell::DrawnSurface after = renderer.drawnSurface(camera, time_s + interval_s);
    const swell::FrameFlow flow = swell::opticalFlowOf(first.labels, time_s, second.labels, interval_s,
                                                       swell::seaMotionOf(scene, renderer.waveModel()));
    const swell::CameraCalibration& c = first.labels.camera;
    const glm::dvec3 eye(c.worldFromCamera[3]);
    const int cells = swell::gridShapeFor(scene.grid, scene.camera).cells;
    std::vector<double> errors_px;
    double largestMotion_px = 0.0;
    // Per pixel, the triangle its range lies nearest to (near a cell's
    // diagonal both splits may pass within the tolerance): how far, and
    // where its point goes.
    std::vector<std::pair<double, glm::dvec2>> best(flow.flow_px.size(), {INFINITY, glm::dvec2(0.0)});
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            const glm::ivec2 corner[4] = {{i, j}, {i + 1, j}, {i, j + 1}, {i + 1, j + 1}};
            glm::dvec3 v0[4], v1[4];
            for (int k = 0; k < 4; ++k) {
                v0[k] = before.vertex(corner[k].x, corner[k].y);
                v1[k] = after.vertex(corner[k].x, corner[k].y);
            }
            if (glm::distance(v0[0], eye) > 60.0)
                continue; // near water, where cells are several pixels wide
            // Both ways of splitting the cell.
            for (const glm::ivec3 t : {glm::ivec3(0, 1, 2), glm::ivec3(1, 3, 2), glm::ivec3(0, 1, 3), glm::ivec3(0, 3, 2)}) {
                const glm::dvec3 tri[3] = {v0[t.x], v0[t.y], v0[t.z]};
                glm::dvec2 lo(1e30), hi(-1e30);
                for (const glm::dvec3& v : tri) {
                    const glm::dvec3 inCamera(c.cameraFromWorld * glm::dvec4(v, 1.0));
                    if (inCamera.z <= 0.0)
                        lo = glm::dvec2(1e30);
                    lo = glm::min(lo, pinholeProject(c, v));
                    hi = glm::max(hi, pinholeProject(c, v));
                }
                for (int y = std::max(0, int(std::floor(lo.y))); y < std::min(size.y, int(std::ceil(hi.y)) + 1); ++y)
                    for (int x = std::max(0, int(std::floor(lo.x))); x < std::min(size.x, int(std::ceil(hi.x)) + 1); ++x) {
                        const std::size_t p = std::size_t(y) * std::size_t(size.x) + std::size_t(x);
                        if (first.labels.semantic[p] != SWELL_LABEL_WATER || !flow.valid[p])
                            continue;
                        const std::optional<TriangleHit> hit = rayHitsTriangle(eye, opticalFlowCentreRay(c, x, y), tri);
                        if (!hit || std::abs(hit->distance_m - first.labels.range_m[p]) > 1e-3)
                            continue; // not the triangle this pixel shows
                        const glm::dvec3 moved = hit->weights.x * v1[t.x] + hit->weights.y * v1[t.y] + hit->weights.z * v1[t.z];
                        const glm::dvec2 expected = pinholeProject(c, moved) - glm::dvec2(x + 0.5, y + 0.5);
                        const double off_m = std::abs(hit->distance_m - first.labels.range_m[p]);
                        if (off_m < best[p].first)
                            best[p] = {off_m, expected};
                    }
            }
        }
    for (std::size_t p = 0; p < best.size(); ++p)
        if (std::isfinite(best[p].first)) {
            errors_px.push_back(glm::length(flowAt(flow, p) - best[p].second));
            largestMotion_px = std::max(largestMotion_px, glm::length(best[p].second));
        }
    std::sort(errors_px.begin(), errors_px.end());
    ASSERT_GT(errors_px.size(), 5000u);
    EXPECT_GT(largestMotion_px, 1.0) << "the water hardly moves: nothing measured";
    // The float32 range's rounding alone: 2e-4 px measured.
    EXPECT_LT(errors_px.back(), 0.01) << "median " << errors_px[errors_px.size() / 2] << " px";
    std::printf("water: worst %.5f px, median %.5f, over %zu pixels moving up to %.2f px\n", errors_px.back(),
                errors_px[errors_px.size() / 2], errors_px.size(), largestMotion_px);
}

// Linear light of an 8-bit sRGB channel.
double linearOf(std::uint8_t v)
{
    const double c = v / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// The image's linear colour at a continuous place (pixel centres at +0.5),
// bilinear; channel k of RGB.
double linearAt(const swell::Image& image, glm::dvec2 place, int k)
{
    const glm::dvec2 p = place - 0.5;
    const glm::ivec2 p0(glm::floor(p));
    const glm::dvec2 f = p - glm::dvec2(p0);
    double sum = 0.0;
    for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx) {
            const int x = std::clamp(p0.x + dx, 0, image.width - 1), y = std::clamp(p0.y + dy, 0, image.height - 1);
            const double w = (dx ? f.x : 1.0 - f.x) * (dy ? f.y : 1.0 - f.y);
            sum += w * linearOf(image.rgba[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4 + std::size_t(k)]);
        }
    return sum;
}

// The frame at t + dt warped back by the flow: each valid pixel of frame t
// against frame t + dt where the flow says its point went.
TEST_F(OpticalFlow, WarpingTheNextFrameBackByTheFlowGivesThisFrame)
{
    swell::Scene scene = swell::test::openSea();
    scene.objects.push_back(boatUnderWay(glm::dvec3(3.0, 0.0, -22.0), -30.0, glm::dvec3(-1.0, 0.0, 0.0)));
    scene.sun.direction = glm::dvec3(0.2, 0.6, 0.8); // behind the camera: no glitter in view
    swell::Renderer renderer(scene);
    const swell::Camera before = cameraLookingNorth(scene, glm::dvec3(0.0, 5.0, 0.0), -14.0);
    swell::Camera after = before;
    after.position_m += glm::dvec3(0.6, 0.0, 0.0); // 18 m/s sideways
    after.yaw_deg += 1.0;                          // and turning 30 degrees a second
    const glm::ivec2 size(240, 180);
    const double time_s = 4.0, interval_s = 1.0 / 30.0; // a clip's frame at 30 frames a second
    const LabelledFrame first = drawFrame(renderer, before, time_s, size);
    const LabelledFrame second = drawFrame(renderer, after, time_s + interval_s, size);
    const swell::FrameFlow flow = swell::opticalFlowOf(first.labels, time_s, second.labels, interval_s,
                                                       swell::seaMotionOf(scene, renderer.waveModel()));
    double warped = 0.0, unwarped = 0.0;
    long long valid = 0;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(size.x) + std::size_t(x);
            if (!flow.valid[i])
                continue;
            const glm::dvec2 centre(x + 0.5, y + 0.5);
            for (int k = 0; k < 3; ++k) {
                const double here = linearAt(first.image, centre, k);
                warped += std::abs(linearAt(second.image, centre + flowAt(flow, i), k) - here);
                unwarped += std::abs(linearAt(second.image, centre, k) - here);
            }
            valid += 1;
        }
    ASSERT_GT(valid, size.x * size.y / 3);
    warped /= 3.0 * double(valid);
    unwarped /= 3.0 * double(valid);
    std::printf("warp: mean absolute error %.5f with the flow, %.5f without, over %lld valid pixels\n", warped,
                unwarped, valid);
    // What the flow cannot carry sets the floor (0.0084 measured): the
    // water's shading follows the waves' phase and the view, not its
    // material points, and bilinear resampling blurs detail a pixel wide
    // (a turn of 0.3 degrees with time stopped leaves 0.003 on the
    // water). Without the flow: 0.027.
    EXPECT_LT(warped, 0.012);
    EXPECT_GT(unwarped, 2.5 * warped);
}

// Every class of the sea moves with it: the coast's surf (a class of its
// own) as the water does. From the coast preset's camera, still, over a
// tenth of a second, the surf's points move with the breaking waves: most
// of them by more than a hundredth of a pixel (a point taken for land stays
// put, and its flow is the still camera's, 0).
TEST_F(OpticalFlow, TheSurfMovesWithTheWater)
{
    const swell::Scene scene = swell::loadScene(std::filesystem::path(SWELL_SOURCE_DIR) / "scenes" / "coast.toml");
    swell::Renderer renderer(scene);
    const swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    const glm::ivec2 size(256, 144);
    const double time_s = 20.0, interval_s = 0.1;
    const LabelledFrame first = drawFrame(renderer, camera, time_s, size);
    const LabelledFrame second = drawFrame(renderer, camera, time_s + interval_s, size);
    const swell::FrameFlow flow = swell::opticalFlowOf(first.labels, time_s, second.labels, interval_s,
                                                       swell::seaMotionOf(scene, renderer.waveModel()));
    int surf = 0, moving = 0;
    for (std::size_t i = 0; i < first.labels.semantic.size(); ++i)
        if (first.labels.semantic[i] == SWELL_LABEL_SURF && flow.valid[i]) {
            ++surf;
            moving += glm::length(flowAt(flow, i)) > 0.01;
        }
    std::printf("surf %d valid pixels, %d moving by more than 0.01 px\n", surf, moving);
    EXPECT_GT(surf, 200);
    EXPECT_GT(moving, surf / 2);
}

} // namespace
