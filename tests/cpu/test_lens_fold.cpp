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

#include <gtest/gtest.h>

#include <string>

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
