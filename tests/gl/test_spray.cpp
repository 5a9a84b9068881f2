// Spray torn from the breaking crests (issue 25, shaders/spray.vert): none
// below Beaufort 7, white mist over the storm's crests at 20 m/s, and every
// particle a function of the simulated time alone, so a still reproduces
// bit for bit whatever was rendered before it.
#include "support/gl_test.h"
#include "swell/renderer.h"
#include "swell/scene_file.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

namespace {

using namespace swell;

class Spray : public test::GlTest {};

constexpr glm::ivec2 kSize{320, 180};
constexpr double kTime_s = 20.0;

Scene storm(double wind_mps, bool spray)
{
    Scene scene = loadScene(std::filesystem::path(SWELL_SOURCE_DIR) / "scenes" / "storm.toml");
    scene.waves.wind->windSpeed_mps = wind_mps;
    scene.water.spray = spray;
    return scene;
}

Image still(const Scene& scene, double time_s = kTime_s)
{
    Renderer renderer(scene);
    return renderer.renderImage(cameraAt(scene.camera, time_s), time_s, kSize);
}

// Pixels that differ, and how many of those the spray made lighter.
struct Change {
    int pixels = 0, lighter = 0;
};

Change changeOf(const Image& off, const Image& on)
{
    Change c;
    for (int y = 0; y < off.height; ++y)
        for (int x = 0; x < off.width; ++x) {
            const std::uint8_t *a = off.pixel(x, y), *b = on.pixel(x, y);
            if (a[0] == b[0] && a[1] == b[1] && a[2] == b[2])
                continue;
            ++c.pixels;
            if (b[0] + b[1] + b[2] > a[0] + a[1] + a[2])
                ++c.lighter;
        }
    return c;
}

TEST_F(Spray, NoneBelowBeaufortSeven)
{
    // 13.8 m/s: Beaufort 6, just below 7's 13.9.
    const Image off = still(storm(13.8, false)), on = still(storm(13.8, true));
    EXPECT_EQ(changeOf(off, on).pixels, 0) << "spray drawn below Beaufort 7";
}

TEST_F(Spray, StormCrestsTrailWhiteMist)
{
    const Image off = still(storm(20.0, false)), on = still(storm(20.0, true));
    const Change c = changeOf(off, on);
    std::printf("storm at 20 m/s: spray changes %d of %d pixels, %d of them lighter\n", c.pixels,
                kSize.x * kSize.y, c.lighter);
    EXPECT_GT(c.pixels, kSize.x * kSize.y / 200) << "too little spray over a gale's breaking crests";
    EXPECT_GT(c.lighter, c.pixels * 9 / 10) << "spray is white mist over a dark sea: it lightens what it covers";
}

TEST_F(Spray, StillsReproduceBitForBitWhateverCameBefore)
{
    const Scene scene = storm(20.0, true);
    const Image first = still(scene), second = still(scene);
    EXPECT_TRUE(first.rgba == second.rgba) << "two stills of the same time differ";
    // A renderer that drew other times first (each more than the foam's
    // longest step away, so the foam of each is its still's: the spray
    // alone could carry anything over) draws the same frame as the still.
    Renderer sequence(scene);
    for (const double t : {5.0, 12.0, 31.0})
        sequence.renderImage(cameraAt(scene.camera, t), t, kSize);
    const Image arrived = sequence.renderImage(cameraAt(scene.camera, kTime_s), kTime_s, kSize);
    EXPECT_EQ(changeOf(first, arrived).pixels, 0) << "the frame depends on the frames before it";
}

} // namespace
