// Shafts of light in the rendered frame (issue 25): seen from under the
// water looking up towards the sun, water.shafts adds the sun's scattered
// light, and under ripples it lies in shafts (its contrast across the image
// grows against flat water's); from above the water it changes no pixel,
// so a view from the air pays nothing for it. tests/gl/test_light_shafts.cpp
// holds the model itself to its closed form.
#include "support/gl_test.h"
#include "support/golden.h"
#include "support/stage.h"
#include "swell/camera.h"
#include "swell/flat_model.h"
#include "swell/renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

namespace {

class LightShaftsRender : public swell::test::GlTest {};

// The linear green of each pixel of a render with the shafts less one
// without: their light alone (8-bit sRGB, so to about 1% of a mid value).
std::vector<double> shaftsLight(const swell::Image& with, const swell::Image& without)
{
    std::vector<double> light;
    for (int y = 0; y < with.height; ++y)
        for (int x = 0; x < with.width; ++x)
            light.push_back(swell::test::srgbToLinear(with.pixel(x, y)[1]) -
                            swell::test::srgbToLinear(without.pixel(x, y)[1]));
    return light;
}

double contrast(const std::vector<double>& v, double* meanOut)
{
    double sum = 0.0, squares = 0.0;
    for (double x : v) {
        sum += x;
        squares += x * x;
    }
    const double mean = sum / double(v.size());
    *meanOut = mean;
    return std::sqrt(std::max(squares / double(v.size()) - mean * mean, 0.0)) / std::max(mean, 1e-9);
}

swell::Scene stage()
{
    swell::Scene scene = swell::test::emptyStage();
    scene.sun.direction = {-0.3, 0.8, -0.5};
    scene.water.absorption_per_m = {0.40, 0.07, 0.09};
    // Ripples 1.5 to 4 m long (slopes a k about 0.16), as the caustics' tests.
    scene.waves.listed.waves = {{{1.0, 0.2}, 4.0, 0.10, 0.3, 0.0},
                                {{0.3, 1.0}, 2.5, 0.06, 0.3, 1.0},
                                {{-0.7, 0.6}, 1.5, 0.04, 0.3, 2.0}};
    return scene;
}

swell::Image render(swell::Scene scene, bool shafts, bool flat, const swell::Camera& camera)
{
    scene.water.shafts = shafts;
    swell::Renderer renderer(scene);
    if (flat)
        renderer.setWaveModel(std::make_shared<swell::FlatModel>());
    return renderer.renderImage(camera, 20.0, {160, 90});
}

TEST_F(LightShaftsRender, UnderTheWaterRipplesMakeShaftsAndAboveItNothingChanges)
{
    const swell::Scene scene = stage();
    // 4 m down, looking level towards the sun's side (the sun lies at
    // azimuth (-0.3, -0.5): yaw so that the view faces it), the lower half
    // of the image the depths, the upper the surface from below.
    swell::Camera below = swell::cameraAt(scene.camera, 0.0);
    below.position_m = {0.0, -4.0, 0.0};
    below.yaw_deg = std::atan2(-0.3, 0.5) * 180.0 / 3.14159265358979;
    below.pitch_deg = 10.0;
    below.fovY_deg = 60.0;
    double flatMean = 0.0, rippledMean = 0.0;
    const double flatContrast =
        contrast(shaftsLight(render(scene, true, true, below), render(scene, false, true, below)), &flatMean);
    const swell::Image rippled = render(scene, true, false, below);
    const double rippledContrast = contrast(shaftsLight(rippled, render(scene, false, false, below)), &rippledMean);
    std::printf("shafts' light 4 m down: flat water mean %.5f contrast %.3f; ripples mean %.5f contrast %.3f\n",
                flatMean, flatContrast, rippledMean, rippledContrast);
    // The shafts add light where the eye is under the water.
    EXPECT_GT(flatMean, 0.002) << swell::test::saveTestImage(rippled, "shafts_rippled.actual");
    EXPECT_GT(rippledMean, 0.002);
    // Ripples break it into shafts: more contrast across the image than
    // flat water's smooth glow (whose own is the phase function's fall-off
    // away from the sun and the surface's window).
    EXPECT_GT(rippledContrast, 1.3 * flatContrast) << swell::test::saveTestImage(rippled, "shafts_rippled.actual");

    // From the air, looking down onto the water: the same image bit for bit.
    swell::Camera above = swell::cameraAt(scene.camera, 0.0);
    above.position_m = {0.0, 5.0, 0.0};
    above.pitch_deg = -30.0;
    const swell::Image with = render(scene, true, false, above), without = render(scene, false, false, above);
    EXPECT_EQ(with.rgba, without.rgba) << "the shafts are seen only from under the water";
}

} // namespace
