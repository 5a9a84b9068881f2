// Each shading effect on a fixed scene: an analytic check that a wrong
// implementation breaks, then a golden image of the scene as judged by eye.
#include "support/stage.h"
#include "support/gl_test.h"
#include "support/golden.h"
#include "swell/renderer.h"

#include <glm/mat4x4.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec4.hpp>

#include <cmath>

namespace {

class Effects : public swell::test::GlTest {};

constexpr glm::ivec2 kEffectsSize{320, 240};

// Still water, no island, a clear sky: the stage for each effect.
swell::Scene stillWater()
{
    swell::Scene scene = swell::test::emptyStage();
    scene.reflection.resolutionScale = 1.0;
    return scene;
}

// Where a world point lands in the image, in pixels from the top left.
glm::dvec2 project(const swell::Camera& camera, glm::dvec3 point)
{
    const glm::dvec3 origin(camera.position_m.x, 0.0, camera.position_m.z);
    const glm::dvec4 clip = camera.projection(double(kEffectsSize.x) / kEffectsSize.y) * camera.viewRelativeTo(origin) *
                            glm::dvec4(point - origin, 1.0);
    const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
    return {(ndc.x * 0.5 + 0.5) * kEffectsSize.x, (0.5 - ndc.y * 0.5) * kEffectsSize.y};
}

double effectsLuminance(const swell::Image& image, int x, int y)
{
    const std::uint8_t* p = image.pixel(x, y);
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

// Red-dominant: the buoy's red in shade (about 105, 33, 32) and its mirror
// image, which at 40 m from 3 m up is 68% of it (Schlick at 86 degrees) over
// the dark water (about 73, 40, 50); sky and water are bluer than red.
bool isBuoyRed(const std::uint8_t* p) { return p[0] > 50 && p[0] > p[1] + 20 && p[0] > p[2] + 10; }

TEST_F(Effects, CalmWaterMirrorsABuoyWhereGeometryPredicts)
{
    swell::Scene scene = stillWater();
    scene.objects.push_back({"builtin:buoy", {0.0, 0.0, -40.0}, 0.0, 2.0, false});
    scene.camera.position_m = {0.0, 3.0, 0.0};
    scene.camera.pitch_deg = -4.0;
    swell::Renderer renderer(scene);
    const swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    const swell::Image image = renderer.renderImage(camera, 0.0, kEffectsSize);
    // The buoy's upper red band ends at y = 2.05 m on scale 1 (4.1 m here),
    // where the white top begins. Directly seen, that edge is the topmost red
    // row; mirrored about the still water (y = -4.1 m) it is the lowest.
    const glm::dvec2 redTop = project(camera, {0.0, 4.1, -40.0});
    const glm::dvec2 mirroredRedTop = project(camera, {0.0, -4.1, -40.0});
    const int column = int(std::lround(redTop.x));
    int highestRed = -1, lowestRed = -1;
    for (int y = 0; y < kEffectsSize.y; ++y)
        if (isBuoyRed(image.pixel(column, y))) {
            if (highestRed < 0)
                highestRed = y;
            lowestRed = y;
        }
    ASSERT_GE(lowestRed, 0) << "no red buoy pixels in column " << column << ": "
                            << swell::test::saveTestImage(image, "mirror.actual");
    // 2 px: the bound (a pixel is 0.19 m at 40 m here); the reflection
    // texture is full size in this scene.
    EXPECT_NEAR(highestRed + 0.5, redTop.y, 2.0) << "the buoy itself is misplaced";
    EXPECT_NEAR(lowestRed + 0.5, mirroredRedTop.y, 2.0) << "its mirror image is misplaced";
    // 48 / 0.6, as for the default scene: llvmpipe repeats its pixels on one
    // machine, and another CPU's math library moves a few pixels on wave and
    // buoy edges by a few levels; a buoy reflected a pixel off moves hundreds.
    swell::test::expectMatchesGolden(image, "effects_mirror", 48, 0.6);
}

TEST_F(Effects, FresnelReflectsMoreAtGrazingAngles)
{
    swell::Scene scene = stillWater();
    scene.water.deepColor = {0.0, 0.02, 0.04};
    scene.sun.intensity = 0.0; // no highlight: only sky reflection and the water body
    swell::Renderer renderer(scene);
    swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    camera.position_m.y = 20.0;
    camera.pitch_deg = -89.0; // looking straight down
    const swell::Image nadir = renderer.renderImage(camera, 0.0, kEffectsSize);
    camera.position_m.y = 2.0;
    camera.pitch_deg = -3.0;
    const swell::Image grazing = renderer.renderImage(camera, 0.0, kEffectsSize);
    const double down = effectsLuminance(nadir, kEffectsSize.x / 2, kEffectsSize.y / 2);
    // Water seen 5 degrees below the horizon: 85 degrees from the normal.
    const glm::dvec2 at = project(camera, {camera.position_m.x, 0.0, camera.position_m.z - 2.0 / std::tan(glm::radians(5.0))});
    const double across = effectsLuminance(grazing, kEffectsSize.x / 2, int(at.y));
    // Schlick with F0 = 0.02: 2% of the sky straight down, 64% at 85 degrees.
    // The sky is ~200 levels bright, so the grazing water must be several times
    // brighter than the nadir water.
    EXPECT_GT(across, 3.0 * down + 20.0) << "nadir " << down << ", grazing " << across;
    EXPECT_LT(down, 45.0) << "looking straight down, water should show its own dark colour";
    // 48 / 0.6: rounding on another CPU moves a few edge pixels by a few
    // levels; a Fresnel exponent of 3 instead of 5 moves the whole grazing
    // band (this golden went red for it).
    swell::test::expectMatchesGolden(grazing, "effects_fresnel_grazing", 48, 0.6);
}

TEST_F(Effects, FullFogMakesHorizonWaterAndSkyTheFogColour)
{
    swell::Scene scene = stillWater();
    scene.fog.start_m = 0.0;
    scene.fog.end_m = 300.0;
    scene.fog.color = {0.5, 0.5, 0.5};
    swell::Renderer renderer(scene);
    swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    camera.pitch_deg = 0.0;
    const swell::Image image = renderer.renderImage(camera, 0.0, kEffectsSize);
    // Linear 0.5 in sRGB is 188 (0.7354 * 255 = 187.5).
    const int expected = 188;
    const int horizon = kEffectsSize.y / 2;
    // Rows 1 and 3 pixels above (sky) and below (water) the horizon: 3 px is
    // 0.75 degrees, where the water 6 m below the eye is 458 m away and the
    // sky's fog layer (2% of the fog end, 6 m, up) likewise: past the 300 m end.
    for (int y : {horizon - 3, horizon - 1, horizon + 1, horizon + 3})
        for (int x = 0; x < kEffectsSize.x; x += 16)
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(image.pixel(x, y)[c], expected, 2) << "pixel " << x << "," << y << " channel " << c;
    // 48 / 0.6: the fogged horizon is flat colour, so only the near water's
    // edges can move with another CPU's rounding; fog off moves the mean by tens.
    swell::test::expectMatchesGolden(image, "effects_fog", 48, 0.6);
}

TEST_F(Effects, RefractionShowsShallowObjectsAndHidesDeepOnes)
{
    auto render = [](double depthOfTop_m, bool withObject) {
        swell::Scene scene = stillWater();
        // A buoy (top at 2.4 m on scale 1) sunk so its top is depthOfTop_m down.
        if (withObject)
            scene.objects.push_back({"builtin:buoy", {0.0, -2.4 - depthOfTop_m, -12.0}, 0.0, 1.0, false});
        scene.camera.position_m = {0.0, 8.0, 0.0};
        scene.camera.pitch_deg = -35.0;
        swell::Renderer renderer(scene);
        return renderer.renderImage(swell::cameraAt(scene.camera, 0.0), 0.0, kEffectsSize);
    };
    const swell::Image empty = render(0.0, false);
    const swell::Image shallow = render(0.3, true);
    const swell::Image deep = render(40.0, true);
    const swell::ImageDifference shallowDiff = swell::compareImages(empty, shallow);
    const swell::ImageDifference deepDiff = swell::compareImages(empty, deep);
    // 0.3 m of water absorbs little: the buoy stands out by tens of levels.
    EXPECT_GT(shallowDiff.maxChannel, 40) << "the shallow buoy is not visible through the water";
    // 40 m absorbs exp(-0.45*40) of red and exp(-0.06*40) = 9% of blue, and the
    // water body colour fills the rest: at most a few levels remain.
    EXPECT_LE(deepDiff.maxChannel, 4) << "the deep buoy should vanish into the water";
    // 48 / 0.6: rounding moves a few edge pixels by a few levels; one
    // absorption coefficient for all channels tints the whole water (red).
    swell::test::expectMatchesGolden(shallow, "effects_refraction_shallow", 48, 0.6);
}

} // namespace
