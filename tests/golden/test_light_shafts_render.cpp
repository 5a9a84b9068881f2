// Shafts of light in the rendered frame (issue 25): seen from under the
// water looking up towards the sun, water.shafts adds the sun's scattered
// light; from above the water it changes no pixel, so a view from the air
// pays nothing for it. tests/gl/test_light_shafts.cpp holds the model itself
// to its closed form, and its shafts under ripples to their contrast and
// mean, in floating point: in a frame's 8 bits the shafts are a few levels
// on the glow's smooth fall-off and the ripples' broken Snell's window.
#include "support/gl_test.h"
#include "support/golden.h"
#include "support/stage.h"
#include "swell/camera.h"
#include "swell/renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
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

double mean(const std::vector<double>& v)
{
    double sum = 0.0;
    for (double x : v)
        sum += x;
    return sum / double(v.size());
}

swell::Scene stage()
{
    swell::Scene scene = swell::test::emptyStage();
    scene.sun.direction = {-0.3, 0.8, -0.5};
    scene.water.absorption_per_m = {0.40, 0.07, 0.09};
    // Ripples 1.5 to 4 m long (slopes a k about 0.16), as the caustics' tests.
    scene.waves.listed = {{{1.0, 0.2}, 4.0, 0.10, 0.3, 0.0},
                                {{0.3, 1.0}, 2.5, 0.06, 0.3, 1.0},
                                {{-0.7, 0.6}, 1.5, 0.04, 0.3, 2.0}};
    return scene;
}

swell::Image render(swell::Scene scene, bool shafts, const swell::Camera& camera)
{
    scene.water.shafts = shafts;
    swell::Renderer renderer(scene);
    return renderer.renderImage(camera, 20.0, {160, 90});
}

TEST_F(LightShaftsRender, UnderTheWaterTheyAddLightAndFromTheAirNothing)
{
    const swell::Scene scene = stage();
    // 4 m down, looking up towards the sun (it lies at azimuth (-0.3, -0.5)
    // and 64 degrees up under the water: yaw so that the view faces it),
    // its glow and the shafts about it in view.
    swell::Camera below = swell::cameraAt(scene.camera, 0.0);
    below.position_m = {0.0, -4.0, 0.0};
    below.yaw_deg = std::atan2(-0.3, 0.5) * 180.0 / 3.14159265358979;
    below.pitch_deg = 45.0;
    below.fovY_deg = 60.0;
    const swell::Image rippled = render(scene, true, below);
    const double light = mean(shaftsLight(rippled, render(scene, false, below)));
    std::printf("shafts' light 4 m down towards the sun: %.5f (linear green, the image's mean)\n", light);
    // The shafts add light where the eye is under the water (measured 0.031;
    // 8-bit levels are 0.002 apart there).
    EXPECT_GT(light, 0.01) << swell::test::saveTestImage(rippled, "shafts_rippled.actual");

    // From the air, looking down onto the water: the same image bit for bit.
    swell::Camera above = swell::cameraAt(scene.camera, 0.0);
    above.position_m = {0.0, 5.0, 0.0};
    above.pitch_deg = -30.0;
    const swell::Image with = render(scene, true, above), without = render(scene, false, above);
    EXPECT_EQ(with.rgba, without.rgba) << "the shafts are seen only from under the water";
}

} // namespace
