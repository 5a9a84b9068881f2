// Kannala-Brandt's fisheye (swell/dataset/sensor.h; docs/SCENE.md "The
// lens"): theta_d against hand-computed values, a world point projected as
// the published equations (Kannala & Brandt 2006, eq. 6, in OpenCV's
// cv2.fisheye form) put it, the focal length that gives the field asked,
// and the refusals: a lens whose theta_d stops growing inside the field, a
// field wider than the pinhole frame holds, and a model's coefficients
// beside the other's, each at its key's line and column.
#include "swell/dataset/sensor.h"

#include "swell/error.h"
#include "swell/scene/scene_file.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace {

swell::LensDistortion fisheye(double k1, double k2, double k3, double k4)
{
    return {k1, k2, k3, 0.0, 0.0, k4, swell::LensModel::KannalaBrandt};
}

// theta_d = theta (1 + k1 theta^2 + k2 theta^4 + k3 theta^6 + k4 theta^8),
// worked by hand: at theta = 0.5 with k = (0.1, 0.01, 0.001, 0.0001) the
// bracket is 1 + 0.025 + 0.000625 + 0.000015625 + 0.000000390625 =
// 1.025641015625, so theta_d = 0.5128205078125; at theta = 1 it is 1.1111.
TEST(FisheyeLens, ThetaDIsKannalaBrandtsPolynomial)
{
    const swell::LensDistortion lens = fisheye(0.1, 0.01, 0.001, 0.0001);
    EXPECT_NEAR(swell::fisheyeThetaD(lens, 0.5), 0.5128205078125, 1e-15);
    EXPECT_NEAR(swell::fisheyeThetaD(lens, 1.0), 1.1111, 1e-15);
    // distort(): the point (a, b) = tan(0.5) (0.6, 0.8), 0.5 rad from the
    // axis, lands theta_d out along the same direction.
    const glm::dvec2 d = swell::distort(lens, std::tan(0.5) * glm::dvec2(0.6, 0.8));
    EXPECT_NEAR(d.x, 0.5128205078125 * 0.6, 1e-15);
    EXPECT_NEAR(d.y, 0.5128205078125 * 0.8, 1e-15);
    // The equidistant fisheye (every k 0) is no pinhole: theta_d = theta.
    EXPECT_FALSE(fisheye(0.0, 0.0, 0.0, 0.0).none());
    EXPECT_NEAR(glm::length(swell::distort(fisheye(0.0, 0.0, 0.0, 0.0), {std::tan(1.2), 0.0})), 1.2, 1e-15);
    // undistort() inverts it.
    const glm::dvec2 u = swell::undistort(lens, d);
    EXPECT_NEAR(u.x, std::tan(0.5) * 0.6, 1e-12);
    EXPECT_NEAR(u.y, std::tan(0.5) * 0.8, 1e-12);
}

// The fisheye's pixel of a camera-axes point, written out from the
// published form (not the library's distort()): theta = atan2(|(x, y)|, z).
glm::dvec2 publishedFisheyePixel(const swell::CameraCalibration& c, glm::dvec3 p)
{
    const double r3 = std::hypot(p.x, p.y), theta = std::atan2(r3, p.z);
    const double t2 = theta * theta;
    const double thetaD = theta * (1.0 + c.k1 * t2 + c.k2 * t2 * t2 + c.k3 * t2 * t2 * t2 + c.k4 * t2 * t2 * t2 * t2);
    return {c.fx_px * thetaD * p.x / r3 + c.cx_px, c.fy_px * thetaD * p.y / r3 + c.cy_px};
}

TEST(FisheyeLens, APointProjectsWhereThePublishedEquationsPutIt)
{
    swell::Camera camera;
    camera.fovY_deg = 80.0;
    camera.position_m = glm::dvec3(1.0, 5.0, 2.0);
    camera.yaw_deg = 35.0;
    camera.pitch_deg = -10.0;
    camera.roll_deg = 7.0;
    const swell::CameraCalibration c = swell::sensorCalibrationOf(camera, fisheye(0.03, -0.01, 0.002, -0.0005), {640, 480});
    ASSERT_EQ(c.lensModel, swell::LensModel::KannalaBrandt);
    ASSERT_EQ(c.k4, -0.0005);
    int checked = 0;
    for (double angle_deg = 0.5; angle_deg < 70.0; angle_deg += 3.1)
        for (double around_deg = 0.0; around_deg < 360.0; around_deg += 23.0) {
            const double a = glm::radians(angle_deg), b = glm::radians(around_deg);
            const glm::dvec3 inCamera = 12.0 * glm::dvec3(std::sin(a) * std::cos(b), std::sin(a) * std::sin(b), std::cos(a));
            const glm::dvec3 world(c.worldFromCamera * glm::dvec4(inCamera, 1.0));
            const std::optional<glm::dvec2> at = swell::projectToImage(c, world);
            ASSERT_TRUE(at) << angle_deg << " deg";
            const glm::dvec2 expected = publishedFisheyePixel(c, inCamera);
            EXPECT_NEAR(at->x, expected.x, 1e-9) << angle_deg << " deg from the axis, " << around_deg << " around";
            EXPECT_NEAR(at->y, expected.y, 1e-9) << angle_deg << " deg from the axis, " << around_deg << " around";
            ++checked;
        }
    EXPECT_GT(checked, 300);
}

// The field asked is the angle between the rays of the top and bottom
// borders' middles: f = (height / 2) / theta_d(fovY / 2).
TEST(FisheyeLens, TheFocalLengthPutsTheFieldsBordersAtHalfTheField)
{
    swell::Camera camera;
    camera.fovY_deg = 100.0;
    const swell::LensDistortion lens = fisheye(-0.02, 0.004, 0.0, 0.0);
    const swell::CameraCalibration c = swell::sensorCalibrationOf(camera, lens, {640, 480});
    const double half = glm::radians(50.0);
    const double thetaD = half * (1.0 - 0.02 * half * half + 0.004 * std::pow(half, 4));
    EXPECT_NEAR(c.fy_px, 240.0 / thetaD, 1e-9);
    EXPECT_EQ(c.fx_px, c.fy_px);
    for (const glm::dvec2 border : {glm::dvec2(320.0, 0.0), glm::dvec2(320.0, 480.0)}) {
        const glm::dvec2 u = swell::undistort(lens, {(border.x - c.cx_px) / c.fx_px, (border.y - c.cy_px) / c.fy_px});
        EXPECT_NEAR(glm::degrees(std::atan(glm::length(u))), 50.0, 1e-9);
    }
}

void expectRefusedAt(const std::string& toml, int line, int column, const std::string& words)
{
    SCOPED_TRACE(toml);
    try {
        const swell::Scene scene = swell::parseScene(toml, "fisheye.toml");
        swell::checkLens(scene, {640, 480}, scene.camera.fovY_deg, "fisheye.toml");
        FAIL() << "taken";
    } catch (const swell::InputError& e) {
        EXPECT_EQ(e.place().path, "fisheye.toml");
        EXPECT_EQ(e.place().line, line) << e.message();
        EXPECT_EQ(e.place().column, column) << e.message();
        EXPECT_NE(e.message().find(words), std::string::npos) << e.message();
    }
}

// k1 = -0.3: theta_d stops growing at theta = 1 / sqrt(0.9), 60.4 degrees,
// short of the corners of a 100 degree field (two places of the scene
// would meet in one pixel).
TEST(FisheyeLens, ALensThatFoldsIsRefusedAtItsFirstCoefficient)
{
    expectRefusedAt("[camera]\nlens = \"kannala_brandt\"\nfov_y_deg = 100.0\nfisheye_k1 = -0.3\nfisheye_k2 = 0.001\n", 4,
                    14, "theta_d stops growing with theta at 60.");
    EXPECT_NE(swell::lensProblem(fisheye(-0.3, 0.0, 0.0, 0.0), 100.0, {640, 480}).find("60.4 degrees"), std::string::npos);
    // The same lens over a field whose corners its theta_d reaches while it
    // grows (40 degrees: theta_d 0.56 at the corners, at most 0.70) is drawn.
    EXPECT_EQ(swell::lensProblem(fisheye(-0.3, 0.0, 0.0, 0.0), 40.0, {640, 480}), "");
}

// The pinhole frame the fisheye is resampled from bounds its field: an
// equidistant fisheye at 640x480 is drawn up to 88 degrees of vertical
// field (147.3 across the diagonal) and refused past it, at camera.lens's
// place when no coefficient is set; 150 degrees puts the corners past 90
// degrees from the axis, where the pinhole frame holds no ray.
TEST(FisheyeLens, AFieldWiderThanItDrawsIsRefusedNamingTheWidest)
{
    EXPECT_EQ(swell::lensProblem(fisheye(0.0, 0.0, 0.0, 0.0), 88.0, {640, 480}), "");
    EXPECT_NE(swell::lensProblem(fisheye(0.0, 0.0, 0.0, 0.0), 89.0, {640, 480}), "");
    expectRefusedAt("[camera]\nfov_y_deg = 100.0\nlens = \"kannala_brandt\"\n", 3, 8,
                    "(the field is 166.7 degrees across the diagonal; a fisheye is drawn up to about 147)");
    expectRefusedAt("[camera]\nfov_y_deg = 150.0\nlens = \"kannala_brandt\"\n", 3, 8,
                    "reach 90 degrees from the axis and more");
}

// A model's coefficients beside the other model are refused at their key.
TEST(FisheyeLens, TheOtherModelsCoefficientsAreRefusedAtTheirKey)
{
    try {
        swell::parseScene("[camera]\nlens = \"kannala_brandt\"\ndistortion_k1 = -0.1\n", "mixed.toml");
        FAIL() << "a Brown-Conrady coefficient taken on a fisheye";
    } catch (const swell::InputError& e) {
        EXPECT_EQ(e.place().line, 3) << e.message();
        EXPECT_NE(e.message().find("camera.distortion_k1 = -0.1: a Brown-Conrady coefficient"), std::string::npos)
            << e.message();
    }
    try {
        swell::parseScene("[camera]\nfov_y_deg = 70.0\nfisheye_k3 = 0.01\n", "mixed.toml");
        FAIL() << "a fisheye coefficient taken on Brown-Conrady's lens";
    } catch (const swell::InputError& e) {
        EXPECT_EQ(e.place().line, 3) << e.message();
        EXPECT_NE(e.message().find("set camera.lens = \"kannala_brandt\""), std::string::npos) << e.message();
    }
}

} // namespace
