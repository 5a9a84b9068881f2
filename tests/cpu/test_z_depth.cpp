// Each pixel's z-depth (swell::zDepthOf, docs/LABELS.md "Conventions"): the
// depth along the camera's optical axis (OpenCV's camera z, by the written
// camera_from_world) of the point the pixel's range measures along its
// centre ray, through a lens as without one; infinity where the range is.
#include "swell/dataset/labels.h"
#include "swell/dataset/sensor.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

TEST(ZDepth, IsThePointsCameraZThroughALensAndWithout)
{
    swell::Camera camera;
    camera.fovY_deg = 70.0;
    camera.position_m = glm::dvec3(4.0, 12.0, -3.0);
    camera.yaw_deg = 40.0;
    camera.pitch_deg = -25.0;
    camera.roll_deg = 9.0;
    for (const double k1 : {0.0, -0.08}) {
        SCOPED_TRACE(::testing::Message() << "k1 " << k1);
        swell::FrameLabels labels;
        labels.size = glm::ivec2(64, 48);
        labels.camera = swell::calibrationOf(camera, labels.size);
        labels.camera.k1 = k1;
        labels.camera.p2 = k1 == 0.0 ? 0.0 : 0.004;
        const swell::CameraCalibration& c = labels.camera;
        const swell::LensDistortion lens{c.k1, c.k2, c.k3, c.p1, c.p2};
        // Each pixel's centre ray meets a point at its own distance (a
        // range of 3 to 400 m), or nothing (the top row).
        std::vector<glm::dvec3> points;
        for (int y = 0; y < labels.size.y; ++y)
            for (int x = 0; x < labels.size.x; ++x) {
                if (y == 0) {
                    labels.range_m.push_back(INFINITY);
                    points.emplace_back(0.0);
                    continue;
                }
                const glm::dvec2 u = swell::undistort(lens, {(x + 0.5 - c.cx_px) / c.fx_px, (y + 0.5 - c.cy_px) / c.fy_px});
                const glm::dvec3 ray = glm::normalize(glm::dmat3(c.worldFromCamera) * glm::dvec3(u, 1.0));
                const double range_m = 3.0 + 397.0 * double((x * 37 + y * 11) % 97) / 96.0;
                labels.range_m.push_back(float(range_m));
                points.push_back(camera.position_m + double(labels.range_m.back()) * ray);
            }
        const std::vector<float> depth = swell::zDepthOf(labels);
        ASSERT_EQ(depth.size(), labels.range_m.size());
        int off = 0;
        for (std::size_t i = 0; i < depth.size(); ++i) {
            if (i < std::size_t(labels.size.x)) {
                off += !std::isinf(depth[i]);
                continue;
            }
            const double z = (c.cameraFromWorld * glm::dvec4(points[i], 1.0)).z;
            off += !(std::abs(depth[i] - z) <= 1e-6 * z);
        }
        EXPECT_EQ(off, 0);
    }
}

} // namespace
