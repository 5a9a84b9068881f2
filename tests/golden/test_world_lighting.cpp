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
#include "swell/scene_file.h"

#include <glm/trigonometric.hpp>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

namespace {

class WorldLighting : public swell::test::GlTest {};

// The sunset preset's light and sky; fog far beyond the rock.
std::string rockScene(const std::string& sunDirection, double sunIntensity)
{
    return "terrain = false\n"
           "[sun]\n"
           "direction = " + sunDirection + "\n"
           "color = [1.0, 0.55, 0.25]\n"
           "intensity = " + std::to_string(sunIntensity) + "\n"
           "[sky]\n"
           "zenith_color = [0.16, 0.2, 0.38]\n"
           "horizon_color = [0.95, 0.55, 0.3]\n"
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
};

double linearLuminance(const std::uint8_t* p)
{
    using swell::test::srgbToLinear;
    return 0.2126 * srgbToLinear(p[0]) + 0.7152 * srgbToLinear(p[1]) + 0.0722 * srgbToLinear(p[2]);
}

// The rock's pixels above the water: where the image with it differs from
// the one without it, in rows above its waterline (below it lies its reflection).
std::vector<RockPixel> rockPixels(const std::string& sunDirection, double sunIntensity, swell::Image& image)
{
    swell::Scene scene = swell::parseScene(rockScene(sunDirection, sunIntensity), "rock.toml");
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
                pixels.push_back({x, y, linearLuminance(a)});
        }
    return pixels;
}

double meanOf(const std::vector<RockPixel>& pixels, auto&& keep)
{
    double sum = 0.0;
    int n = 0;
    for (const RockPixel& p : pixels)
        if (keep(p)) {
            sum += p.luminance;
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

} // namespace
