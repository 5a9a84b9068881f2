// World objects are lit by the sun on the sun's side (issue 28, item 11: the
// sunset's rock looked lit on the camera's side with the sun behind it).
//
// The built-in rock stands in calm water under the sunset preset's sky (a
// bright orange horizon, a dark blue zenith) and its low sun. Its pixels are
// those that change when it is left out, above its waterline; their mean
// luminance (linear) is compared between halves, or with the sun put out.
#include "support/gl_test.h"
#include "support/golden.h"
#include "swell/camera.h"
#include "swell/flat_model.h"
#include "swell/renderer.h"
#include "swell/scene/scene_file.h"

#include <glm/trigonometric.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

namespace {

class WorldLighting : public swell::test::GlTest {};

// The gradient sky the sunset preset had before it took the physical one.
const std::string kGradientSunsetSky = "[sky]\n"
                                       "zenith_color = [0.16, 0.2, 0.38]\n"
                                       "horizon_color = [0.95, 0.55, 0.3]\n";
// The sunset preset's physical sky (scenes/sunset.toml).
const std::string kPhysicalSunsetSky = "[sky]\n"
                                       "model = \"physical\"\n"
                                       "exposure = 12.0\n";

// A sunset's light and sky; fog far beyond the rock.
std::string rockScene(const std::string& sunDirection, double sunIntensity, const std::string& sky = kGradientSunsetSky)
{
    return "terrain = false\n"
           "[sun]\n"
           "direction = " + sunDirection + "\n"
           "color = [1.0, 0.55, 0.25]\n"
           "intensity = " + std::to_string(sunIntensity) + "\n"
           + sky +
           "[fog]\n"
           "start_m = 5000.0\n"
           "end_m = 9000.0\n"
           "[[objects]]\n"
           "path = \"builtin:rock\"\n"
           "position_m = [0.0, 0.0, -25.0]\n"
           "[camera]\n"
           "position_m = [0.0, 1.0, 0.0]\n"
           "pitch_deg = 0.0\n"
           "fov_y_deg = 40.0\n";
}

struct RockPixel {
    int x, y;
    double luminance; // linear
    double red, blue; // linear
};

double linearLuminance(const std::uint8_t* p)
{
    using swell::test::srgbToLinear;
    return 0.2126 * srgbToLinear(p[0]) + 0.7152 * srgbToLinear(p[1]) + 0.0722 * srgbToLinear(p[2]);
}

// The rock's pixels above the water: where the image with it differs from
// the one without it, in rows above its waterline (below it lies its reflection).
std::vector<RockPixel> rockPixels(const std::string& sunDirection, double sunIntensity, swell::Image& image,
                                  const std::string& sky = kGradientSunsetSky)
{
    swell::Scene scene = swell::parseScene(rockScene(sunDirection, sunIntensity, sky), "rock.toml");
    scene.antialiasing = swell::Antialiasing::Off;
    const glm::ivec2 size{480, 270};
    const swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    swell::Renderer with(scene);
    with.setWaveModel(std::make_shared<swell::FlatModel>());
    image = with.renderImage(camera, 0.0, size);
    scene.objects.clear();
    swell::Renderer without(scene);
    without.setWaveModel(std::make_shared<swell::FlatModel>());
    const swell::Image empty = without.renderImage(camera, 0.0, size);
    // The rock's foot on the water, 25 m ahead and 1 m below the eye.
    const double half = 0.5 * size.y;
    const double waterline = half + (1.0 / 25.0) / std::tan(glm::radians(0.5 * camera.fovY_deg)) * half;
    std::vector<RockPixel> pixels;
    for (int y = 0; y < int(waterline) - 1; ++y)
        for (int x = 0; x < size.x; ++x) {
            const std::uint8_t* a = image.pixel(x, y);
            const std::uint8_t* b = empty.pixel(x, y);
            if (std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]) > 24)
                pixels.push_back({x, y, linearLuminance(a), swell::test::srgbToLinear(a[0]), swell::test::srgbToLinear(a[2])});
        }
    return pixels;
}

double meanOf(const std::vector<RockPixel>& pixels, auto&& keep, double RockPixel::*value = &RockPixel::luminance)
{
    double sum = 0.0;
    int n = 0;
    for (const RockPixel& p : pixels)
        if (keep(p)) {
            sum += p.*value;
            ++n;
        }
    return n > 0 ? sum / n : 0.0;
}

// The sun low behind the rock, as in the sunset: the side the camera sees
// is the one the sun does not reach, so it has the sky's and the sea's light
// alone. The same view with the sun put out differs only on the rock's rim
// (faces turned across the view, which the low sun grazes): the visible side
// is at most 15% brighter on the mean. Were the rock lit on the camera's side
// (normals turned inwards, a back face's normal not turned round, the sun's
// direction reversed), that side would take the sun's full light, 2.5 times
// the sky's.
TEST_F(WorldLighting, WithTheSunBehindTheSideTheCameraSeesHasNoSunlight)
{
    swell::Image lit, unlit;
    const std::vector<RockPixel> withSun = rockPixels("[0.0, 0.07, -1.0]", 2.5, lit);
    const std::vector<RockPixel> withoutSun = rockPixels("[0.0, 0.07, -1.0]", 0.0, unlit);
    ASSERT_GT(withSun.size(), 500u) << swell::test::saveTestImage(lit, "world_lighting_behind");
    ASSERT_GT(withoutSun.size(), 500u) << swell::test::saveTestImage(unlit, "world_lighting_behind_unlit");
    const double sun = meanOf(withSun, [](const RockPixel&) { return true; });
    const double sky = meanOf(withoutSun, [](const RockPixel&) { return true; });
    EXPECT_LT(sun, 1.15 * sky) << "camera's side " << sun << " with the sun behind, " << sky << " without it: "
                               << swell::test::saveTestImage(lit, "world_lighting_behind");
}

// The sun low on the left: the rock's left half is lit, its right half is in
// its own shadow, several times darker (direct sunlight 2.5 times the sky's
// light at most against the sky's and the sea's light alone).
TEST_F(WorldLighting, WithTheSunOnOneSideThatSideIsTheLitOne)
{
    for (const bool left : {true, false}) {
        swell::Image image;
        const std::vector<RockPixel> rock = rockPixels(left ? "[-1.0, 0.07, 0.0]" : "[1.0, 0.07, 0.0]", 2.5, image);
        ASSERT_GT(rock.size(), 500u);
        double sumX = 0.0;
        for (const RockPixel& p : rock)
            sumX += p.x;
        const double centre = sumX / double(rock.size());
        const double leftHalf = meanOf(rock, [&](const RockPixel& p) { return p.x < centre; });
        const double rightHalf = meanOf(rock, [&](const RockPixel& p) { return p.x >= centre; });
        const double sunSide = left ? leftHalf : rightHalf, shadowSide = left ? rightHalf : leftHalf;
        EXPECT_GT(sunSide, 2.0 * shadowSide)
            << "sun on the " << (left ? "left" : "right") << ": sun's side " << sunSide << ", other side " << shadowSide
            << ": " << swell::test::saveTestImage(image, left ? "world_lighting_left" : "world_lighting_right");
    }
}

// Issue 28 item 11 itself: at sunset the sky opposite the low sun is dim and
// bluish, so the rock's side away from the sun, which only the sky and the
// sea light, must be bluish and dark. Under the physical sky (the sunset
// preset's), with the sun 4 degrees up on the left: the right half's blue
// over red exceeds the rock's own albedo's (0.37 / 0.42), so the light on it
// is bluer than white, and its mean luminance is under a quarter of the lit
// half's. The gradient sky's ambient (a mix of its orange horizon and blue
// zenith) made that side warm: with it in place of the physical sky's,
// blue over red was 0.828 against the albedo's 0.881 (measured at an
// exposure of 16; a ratio, it does not depend on it), and the
// test fails; the luminance alone (0.23 of the lit half's then) does not
// tell the two apart.
TEST_F(WorldLighting, AtSunsetTheSideAwayFromTheSunIsDimAndBluish)
{
    swell::Image image;
    const std::vector<RockPixel> rock = rockPixels("[-1.0, 0.07, 0.0]", 2.5, image, kPhysicalSunsetSky);
    ASSERT_GT(rock.size(), 500u) << swell::test::saveTestImage(image, "world_lighting_sunset");
    double sumX = 0.0;
    for (const RockPixel& p : rock)
        sumX += p.x;
    const double centre = sumX / double(rock.size());
    auto sunSide = [&](const RockPixel& p) { return p.x < centre; };
    auto shadeSide = [&](const RockPixel& p) { return p.x >= centre; };
    const double albedoBlueOverRed = 0.37 / 0.42; // src/assets/mesh_data.cpp's rock
    const double shadeBlueOverRed = meanOf(rock, shadeSide, &RockPixel::blue) / meanOf(rock, shadeSide, &RockPixel::red);
    const double sunBlueOverRed = meanOf(rock, sunSide, &RockPixel::blue) / meanOf(rock, sunSide, &RockPixel::red);
    const double shade = meanOf(rock, shadeSide), lit = meanOf(rock, sunSide);
    std::printf("sunset rock: away from the sun blue/red %.3f (albedo %.3f), luminance %.4f; sun's side %.3f, %.4f\n",
                shadeBlueOverRed, albedoBlueOverRed, shade, sunBlueOverRed, lit);
    EXPECT_GT(shadeBlueOverRed, albedoBlueOverRed)
        << "the side away from the sun is not lit by a bluish sky: " << swell::test::saveTestImage(image, "world_lighting_sunset");
    EXPECT_LT(sunBlueOverRed, albedoBlueOverRed) << "the sun's side is not lit warm";
    EXPECT_LT(shade, 0.25 * lit) << swell::test::saveTestImage(image, "world_lighting_sunset");
}

} // namespace
