// The horizon of the labels (swell/dataset/labels.h): the true horizon's dip for an
// eye above a round Earth against the navigators' table (Bowditch 2002,
// The American Practical Navigator, table 22: the geometric dip is
// 1.93 arc minutes times the square root of the height in metres), and the
// true horizon's points in the image looking out at exactly that dip, on
// the sea's side of the flat sea's line, for a rolled camera.
#include "swell/dataset/labels.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

namespace {

TEST(Horizon, TheTrueHorizonsDipIsTheNavigatorsGeometricDip)
{
    for (double height : {2.0, 10.0, 50.0, 300.0}) {
        const double published_arcmin = 1.93 * std::sqrt(height);
        EXPECT_NEAR(glm::degrees(swell::horizonDip_rad(height)) * 60.0, published_arcmin, 0.01 * published_arcmin)
            << "at " << height << " m";
    }
    EXPECT_EQ(swell::horizonDip_rad(0.0), 0.0);
    EXPECT_EQ(swell::horizonDip_rad(-3.0), 0.0);
}

TEST(Horizon, TheTrueHorizonLooksOutAtItsDipBelowTheFlatSeasLine)
{
    swell::Camera camera;
    camera.position_m = glm::dvec3(5.0, 50.0, -3.0);
    camera.roll_deg = 15.0;
    camera.pitch_deg = -2.0;
    camera.yaw_deg = 40.0;
    const swell::CameraCalibration c = swell::calibrationOf(camera, {640, 480});
    const swell::HorizonLine flat = swell::horizonOf(c);
    const std::vector<glm::dvec2> points = swell::trueHorizonOf(c, 50.0);
    ASSERT_GT(points.size(), 200u);
    const double dip = swell::horizonDip_rad(50.0);
    for (const glm::dvec2& p : points) {
        const glm::dvec3 d = glm::normalize(glm::dmat3(c.worldFromCamera) *
                                            glm::dvec3((p.x - c.cx_px) / c.fx_px, (p.y - c.cy_px) / c.fy_px, 1.0));
        ASSERT_NEAR(std::asin(d.y), -dip, 1e-9);
        // Below the flat line, by dip * f pixels where the line passes the
        // image's centre (1.65 px here) and more off the axis.
        const double below_px = -glm::dot(flat.line, glm::dvec3(p, 1.0));
        ASSERT_GT(below_px, 0.99 * dip * c.fy_px);
        ASSERT_LT(below_px, 2.0 * dip * c.fy_px);
    }
}

} // namespace
