// Spray torn from the breaking crests (issue 25, shaders/spray.vert): none
// below Beaufort 7, white mist over the storm's crests at 20 m/s drawn out
// in streaks along the wind, and every particle a function of the simulated
// time alone, so a still reproduces bit for bit whatever was rendered
// before it.
#include "support/gl_test.h"
#include "swell/renderer.h"
#include "swell/scene/scene_file.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace {

using namespace swell;

class Spray : public test::GlTest {};

constexpr glm::ivec2 kSpraySize{320, 180};
constexpr double kSprayTime_s = 20.0;

Scene storm(double wind_mps, bool spray)
{
    Scene scene = loadScene(std::filesystem::path(SWELL_SOURCE_DIR) / "scenes" / "storm.toml");
    scene.sea.wind->windSpeed_mps = wind_mps;
    scene.water.spray = spray;
    // In the sun, the storm's overcast deck opened: under it the spray over
    // the whitecaps' foam is about as bright as the foam (measured: 883 of
    // 1613 changed pixels lighter), which would blur what these tests ask.
    scene.sky.clouds.cover = 0.0;
    return scene;
}

Image still(const Scene& scene, double time_s = kSprayTime_s, glm::ivec2 size = kSpraySize)
{
    Renderer renderer(scene);
    return renderer.renderImage(cameraAt(scene.camera, time_s), time_s, size);
}

// Pixels that differ, and how many of those the spray made lighter.
struct SprayChange {
    int pixels = 0, lighter = 0;
};

SprayChange changeOf(const Image& off, const Image& on)
{
    SprayChange c;
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
    const SprayChange c = changeOf(off, on);
    std::printf("storm at 20 m/s: spray changes %d of %d pixels, %d of them lighter\n", c.pixels,
                kSpraySize.x * kSpraySize.y, c.lighter);
    EXPECT_GT(c.pixels, kSpraySize.x * kSpraySize.y / 200) << "too little spray over a gale's breaking crests";
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
        sequence.renderImage(cameraAt(scene.camera, t), t, kSpraySize);
    const Image arrived = sequence.renderImage(cameraAt(scene.camera, kSprayTime_s), kSprayTime_s, kSpraySize);
    EXPECT_EQ(changeOf(first, arrived).pixels, 0) << "the frame depends on the frames before it";
}

// The spray's streaks: what the spray adds to each pixel's brightness, and
// the orientation of that pattern (the structure tensor of its gradient:
// Bigun and Granlund 1987). Its coherence, (l1 - l2) / (l1 + l2) of the
// tensor's eigenvalues, is 0 for round puffs and 1 for parallel lines.
struct Streaks {
    double orientation_deg = 0.0; // of the lines, image axes (x right, y down), 0..180
    double coherence = 0.0;
    glm::dvec2 centroid{0.0};     // of the added brightness, pixels
};

Streaks streaksOf(const Image& off, const Image& on)
{
    auto added = [&](int x, int y) {
        const std::uint8_t *a = off.pixel(x, y), *b = on.pixel(x, y);
        return std::max(0.0, double(b[0] + b[1] + b[2]) - double(a[0] + a[1] + a[2]));
    };
    double jxx = 0.0, jyy = 0.0, jxy = 0.0, sum = 0.0;
    Streaks s;
    for (int y = 1; y + 1 < off.height; ++y)
        for (int x = 1; x + 1 < off.width; ++x) {
            const double gx = 0.5 * (added(x + 1, y) - added(x - 1, y));
            const double gy = 0.5 * (added(x, y + 1) - added(x, y - 1));
            jxx += gx * gx;
            jyy += gy * gy;
            jxy += gx * gy;
            const double a = added(x, y);
            sum += a;
            s.centroid += a * glm::dvec2(x + 0.5, y + 0.5);
        }
    s.centroid /= std::max(sum, 1e-9);
    const double root = std::sqrt((jxx - jyy) * (jxx - jyy) + 4.0 * jxy * jxy);
    s.coherence = root / std::max(jxx + jyy, 1e-9);
    // The gradient's main direction is across the lines.
    const double across_deg = 0.5 * std::atan2(2.0 * jxy, jxx - jyy) * 180.0 / 3.14159265358979;
    s.orientation_deg = std::fmod(across_deg + 90.0 + 360.0, 180.0);
    return s;
}

// The wind's direction in the image (0..180 degrees, x right, y down) on
// the sea's mean level under a pixel.
double imageWindAt(const Scene& scene, glm::ivec2 size, glm::dvec2 pixel)
{
    const Camera camera = cameraAt(scene.camera, kSprayTime_s);
    const glm::dmat4 viewProj = camera.projection(double(size.x) / size.y) * camera.viewRelativeTo(camera.position_m);
    const glm::dmat4 inverse = glm::inverse(viewProj);
    const glm::dvec2 ndc(2.0 * pixel.x / size.x - 1.0, 1.0 - 2.0 * pixel.y / size.y);
    const glm::dvec4 p = inverse * glm::dvec4(ndc, 0.5, 1.0);
    const glm::dvec3 ray = glm::normalize(glm::dvec3(p) / p.w);
    const glm::dvec3 sea = ray * (-camera.position_m.y / ray.y);
    const double direction_rad = scene.sea.wind->windDirection_deg * 3.14159265358979 / 180.0;
    const glm::dvec3 downwind = sea + 0.5 * glm::dvec3(std::cos(direction_rad), 0.0, std::sin(direction_rad));
    auto toPixel = [&](glm::dvec3 q) {
        const glm::dvec4 c = viewProj * glm::dvec4(q, 1.0);
        return glm::dvec2((c.x / c.w + 1.0) * 0.5 * size.x, (1.0 - c.y / c.w) * 0.5 * size.y);
    };
    const glm::dvec2 d = toPixel(downwind) - toPixel(sea);
    return std::fmod(std::atan2(d.y, d.x) * 180.0 / 3.14159265358979 + 360.0, 180.0);
}

// Gale spray is fine mist torn off the crests and drawn out downwind: what
// it adds to the storm's frame lies in lines along the wind's direction in
// the image, not in round puffs.
TEST_F(Spray, StreaksRunDownwind)
{
    const glm::ivec2 size{640, 360};
    const Scene off = storm(20.0, false), on = storm(20.0, true);
    const Streaks s = streaksOf(still(off, kSprayTime_s, size), still(on, kSprayTime_s, size));
    const double wind_deg = imageWindAt(on, size, s.centroid);
    double apart_deg = std::abs(s.orientation_deg - wind_deg);
    apart_deg = std::min(apart_deg, 180.0 - apart_deg);
    std::printf("spray streaks at %.1f deg (coherence %.2f) about pixel (%.0f, %.0f), the wind there at %.1f deg\n",
                s.orientation_deg, s.coherence, s.centroid.x, s.centroid.y, wind_deg);
    EXPECT_GT(s.coherence, 0.4) << "the spray's pattern is not drawn out in lines";
    EXPECT_LT(apart_deg, 15.0) << "the spray's lines do not run along the wind";
}

} // namespace
