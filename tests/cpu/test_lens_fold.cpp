// Which lenses a frame can be drawn through (swell/dataset/sensor.h, lensProblem,
// checkLens; docs/SCENE.md "The lens"): one rule for scenes, sweeps and
// Python. A lens that folds the image is refused (every border pixel
// needs a ray, found to 1e-9; the lens must not fold between the centre
// and that ray; the pinhole frame must stay within 4 times the image),
// naming the coefficients set at the first one's line, and a lens within
// it is drawn.
#include "swell/dataset/sensor.h"

#include "swell/error.h"
#include "swell/scene/scene_file.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace {

TEST(LensFold, AStrongerFoldThanTheOneRefusedBeforeIsRefusedToo)
{
    // k1 = k2 = k3 = -1 at 150 degrees: the fixed-point undistortion never
    // converged, and its result passed the old size test.
    const swell::LensDistortion fold{-1.0, -1.0, -1.0, 0.0, 0.0};
    EXPECT_NE(swell::lensProblem(fold, 150.0, {64, 36}), "");
    EXPECT_NE(swell::lensProblem(fold, 150.0, {640, 480}), "");
}

TEST(LensFold, OrdinaryLensesAreDrawn)
{
    for (const swell::LensDistortion lens : {swell::LensDistortion{-0.1, 0.0, 0.0, 0.0, 0.0},
                                             swell::LensDistortion{0.2, 0.05, 0.0, 0.0, 0.0},
                                             swell::LensDistortion{-0.05, 0.01, 0.0, 0.001, -0.002}})
        EXPECT_EQ(swell::lensProblem(lens, 60.0, {640, 480}), "") << lens.k1;
    EXPECT_EQ(swell::lensProblem({}, 150.0, {16384, 1}), "");
}

// k1 = -1, k3 = 0.5: the radial map turns back between 0.69 and 0.77 focal
// lengths out and climbs again, so for a wide enough image the iteration
// finds a ray on the far side of the fold: refused for the fold on the way.
TEST(LensFold, AFoldBetweenTheCentreAndTheBorderIsRefused)
{
    const swell::LensDistortion lens{-1.0, 0.0, 0.5, 0.0, 0.0};
    int between = 0;
    for (double fov = 20.0; fov <= 150.0; fov += 2.0)
        between += swell::lensProblem(lens, fov, {64, 36}).find("between its centre") != std::string::npos;
    EXPECT_GT(between, 0);
}

TEST(LensFold, TheRefusalNamesTheCoefficientsSetAtTheFirstOnesLine)
{
    const swell::Scene scene = swell::parseScene("[camera]\nfov_y_deg = 120.0\ndistortion_p1 = 0.1\n"
                                                 "distortion_p2 = 0.1\n",
                                                 "lens.toml");
    try {
        swell::checkLens(scene, {64, 36}, scene.camera.fovY_deg, "lens.toml");
        FAIL() << "a lens that folds was taken";
    } catch (const swell::InputError& e) {
        EXPECT_EQ(e.place().path, "lens.toml");
        EXPECT_EQ(e.place().line, 3);
        EXPECT_NE(e.message().find("camera.distortion_p1 = 0.1 and camera.distortion_p2 = 0.1"), std::string::npos)
            << e.message();
        EXPECT_EQ(e.message().find("distortion_k1"), std::string::npos) << e.message();
    }
}

} // namespace

namespace {

// Issue 46: a lens's horizon points are only where the image shows them.
// k1 = -0.2 at a 50 degree field (640x480) is within the lens rule, but folds
// 1.29 focal lengths out (1 / sqrt(0.6)): the pinhole horizon's points and
// the true horizon's directions past it were distorted back into the
// image, 10 to 22 degrees below the horizon the pixels there show. Every
// point written must lie on its horizon by the ray its pixel shows
// (undistort()).
struct FoldedHorizon {
    swell::CameraCalibration camera;
    double height_m = 10.0;
};

FoldedHorizon foldedHorizon(double pitch_deg, double roll_deg)
{
    swell::Camera camera;
    camera.fovY_deg = 50.0;
    camera.position_m = glm::dvec3(3.0, 10.0, -7.0);
    camera.yaw_deg = 30.0;
    camera.pitch_deg = pitch_deg;
    camera.roll_deg = roll_deg;
    FoldedHorizon f;
    f.camera = swell::calibrationOf(camera, {640, 480});
    f.camera.k1 = -0.2;
    EXPECT_EQ(swell::lensProblem({f.camera.k1, 0.0, 0.0, 0.0, 0.0}, camera.fovY_deg, f.camera.size), "");
    return f;
}

// The elevation, degrees, of the ray the image shows at pixel point p.
double shownElevation_deg(const swell::CameraCalibration& c, glm::dvec2 p)
{
    const swell::LensDistortion lens{c.k1, c.k2, c.k3, c.p1, c.p2};
    const glm::dvec2 u = swell::undistort(lens, {(p.x - c.cx_px) / c.fx_px, (p.y - c.cy_px) / c.fy_px});
    const glm::dvec3 d = glm::normalize(glm::dmat3(c.worldFromCamera) * glm::dvec3(u, 1.0));
    return glm::degrees(std::asin(d.y));
}

TEST(LensFold, TheHorizonsPointsAreWhereTheImageShowsTheHorizon)
{
    for (const auto& [pitch, roll] : {std::pair{-20.0, 0.0}, std::pair{-20.0, 12.0}, std::pair{15.0, -8.0}}) {
        SCOPED_TRACE(::testing::Message() << "pitch " << pitch << ", roll " << roll);
        const FoldedHorizon f = foldedHorizon(pitch, roll);
        const swell::HorizonLine line = swell::horizonOf(f.camera);
        const std::vector<glm::dvec2> curve = swell::horizonCurveOf(f.camera, line);
        EXPECT_GT(curve.size(), 100u);
        int off = 0;
        double worst_deg = 0.0;
        for (const glm::dvec2& p : curve) {
            const double e = std::abs(shownElevation_deg(f.camera, p));
            worst_deg = std::max(worst_deg, e);
            off += e > 1e-6;
        }
        EXPECT_EQ(off, 0) << "of " << curve.size() << " curve points, worst " << worst_deg << " deg off the horizon";
        const double dip_deg = glm::degrees(swell::horizonDip_rad(f.height_m));
        const std::vector<glm::dvec2> truePoints = swell::trueHorizonOf(f.camera, f.height_m);
        EXPECT_GT(truePoints.size(), 100u);
        off = 0;
        worst_deg = 0.0;
        for (const glm::dvec2& p : truePoints) {
            const double e = std::abs(shownElevation_deg(f.camera, p) + dip_deg);
            worst_deg = std::max(worst_deg, e);
            off += e > 1e-6;
        }
        EXPECT_EQ(off, 0) << "of " << truePoints.size() << " true horizon points, worst " << worst_deg << " deg off";
    }
}

// A point past the fold is not projected; one inside it is, where the image shows it.
TEST(LensFold, APointPastTheFoldIsNotInTheImage)
{
    const FoldedHorizon f = foldedHorizon(0.0, 0.0);
    const glm::dvec3 eye(f.camera.worldFromCamera[3]);
    const glm::dmat3 toWorld(f.camera.worldFromCamera);
    EXPECT_FALSE(swell::projectToImage(f.camera, eye + toWorld * glm::dvec3(1.35, 0.0, 1.0)));
    EXPECT_FALSE(swell::insideFold({-0.2, 0.0, 0.0, 0.0, 0.0}, {1.3, 0.0}));
    EXPECT_TRUE(swell::insideFold({-0.2, 0.0, 0.0, 0.0, 0.0}, {1.28, 0.0}));
    const std::optional<glm::dvec2> in = swell::projectToImage(f.camera, eye + toWorld * glm::dvec3(0.5, -0.2, 1.0));
    ASSERT_TRUE(in);
    const swell::LensDistortion lens{f.camera.k1, 0.0, 0.0, 0.0, 0.0};
    const glm::dvec2 u = swell::undistort(lens, {(in->x - f.camera.cx_px) / f.camera.fx_px, (in->y - f.camera.cy_px) / f.camera.fy_px});
    EXPECT_NEAR(u.x, 0.5, 1e-9);
    EXPECT_NEAR(u.y, -0.2, 1e-9);
}

} // namespace
