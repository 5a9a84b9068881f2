// Light through the crests (shaders/subsurface.glsl): with the sun low ahead,
// the light the subsurface term adds to the water is blue-green and sits on
// the crests; with the sun behind the camera it is all but gone.
#include "support/gl_test.h"
#include "support/golden.h"
#include "swell/debug.h"
#include "swell/gpu/variants.h"
#include "swell/renderer.h"

#include <glm/geometric.hpp>

#include <cstdio>

namespace {

class Subsurface : public swell::test::GlTest {};

constexpr glm::ivec2 kSubsurfaceSize{320, 180};

// A 12 m/s sea, nothing else, the camera 3 m up looking along -z.
swell::Scene sea(glm::dvec3 sunDirection)
{
    swell::Scene scene = swell::defaultScene();
    scene.objects.clear();
    scene.showTerrain = false;
    scene.sea.wind->windSpeed_mps = 12.0;
    scene.camera.position_m = {0.0, 3.0, 0.0};
    scene.camera.pitch_deg = -8.0;
    scene.sun.direction = glm::normalize(sunDirection);
    return scene;
}

struct Added {
    double red = 0.0, green = 0.0, blue = 0.0; // summed over the image, 0..255 per pixel
};

// What the subsurface term adds: the full image minus the one without it.
Added addedLight(const swell::Scene& scene)
{
    swell::Renderer full(scene);
    const std::unique_ptr<swell::Renderer> without = swell::RendererTesting::create(scene, {}, SWELL_TERM_SUBSURFACE);
    const swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    const swell::Image a = full.renderImage(camera, 2.0, kSubsurfaceSize), b = without->renderImage(camera, 2.0, kSubsurfaceSize);
    Added added;
    for (int y = 0; y < kSubsurfaceSize.y; ++y)
        for (int x = 0; x < kSubsurfaceSize.x; ++x) {
            const std::uint8_t *p = a.pixel(x, y), *q = b.pixel(x, y);
            added.red += double(p[0]) - q[0];
            added.green += double(p[1]) - q[1];
            added.blue += double(p[2]) - q[2];
        }
    return added;
}

TEST_F(Subsurface, BacklitCrestsGlowBlueGreen)
{
    // The sun 8 degrees up, straight ahead: the crests are lit from behind.
    const Added ahead = addedLight(sea({0.0, 0.14, -1.0}));
    // The same sun behind the camera: forward scattering sends nothing back.
    const Added behind = addedLight(sea({0.0, 0.14, 1.0}));
    std::printf("added light, sun ahead: R %.0f G %.0f B %.0f; sun behind: R %.0f G %.0f B %.0f\n", ahead.red,
                ahead.green, ahead.blue, behind.red, behind.green, behind.blue);
    // Visible: on average at least one level per water pixel in green or blue.
    EXPECT_GT(ahead.green + ahead.blue, 2.0 * kSubsurfaceSize.x * kSubsurfaceSize.y / 2);
    // Blue-green: the water absorbs red first. In linear light the added
    // blue is about 2.7 times the red here; sRGB encoding compresses the
    // ratio of the 8-bit levels (measured: G 1.8x, B 1.4x). White light
    // (no absorption) would add equal levels.
    EXPECT_GT(ahead.green, 1.5 * ahead.red);
    EXPECT_GT(ahead.blue, 1.2 * ahead.red);
    // Forward scattering: from behind, under a tenth of it.
    EXPECT_LT(behind.green + behind.blue, 0.1 * (ahead.green + ahead.blue));
}

} // namespace
