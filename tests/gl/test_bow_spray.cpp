// Spray from the bow of a hull under way (issue 25, the spray's passes built
// with SWELL_BOW_SPRAY; objects/bow_spray.h): scenes/gale-under-way.toml's
// boat at 5 m/s in a gale throws white sheets from its bow, on both sides,
// carried downwind; none below Beaufort 7, none from the same hull at rest,
// and a still reproduces bit for bit whatever was rendered before it.
//
// Where the crest spray would blur what these tests ask, the sea makes no
// whitecap foam (waves.foam_lifetime_s = 0): no crest says it broke, so
// there is no crest spray (NoneFromAHullAtRest checks that, spray on and
// off giving the same frame), and what spray there is comes from the bow
// alone.
#include "support/gl_test.h"
#include "swell/renderer.h"
#include "swell/scene/scene_file.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace {

using namespace swell;

class BowSpray : public test::GlTest {};

constexpr glm::ivec2 kBowSpraySize{320, 180};
// At t = 0 a body under way passes its position_m (docs/BODIES.md): the
// hull under way and the hull at rest are in the same place.
constexpr double kBowSprayTime_s = 0.0;
// The preset's heading of travel, 40 degrees from +x towards +z.
const glm::dvec3 kHeading(0.766044443, 0.0, 0.642787610);

Scene gale(double wind_mps, bool spray, double speed_mps, bool crestSpray = false)
{
    Scene scene = loadScene(std::filesystem::path(SWELL_SOURCE_DIR) / "scenes" / "gale-under-way.toml");
    scene.sea.wind->windSpeed_mps = wind_mps;
    scene.water.spray = spray;
    if (!crestSpray)
        scene.waves.foamLifetime_s = 0.0;
    scene.objects.at(0).velocity_m_per_s = kHeading * speed_mps;
    // Six seconds of steps, and no wake (its steps would cost the most):
    // the spray needs neither more history nor the wake.
    scene.historyStart_s = kBowSprayTime_s - 6.0;
    scene.wake.enabled = false;
    // The deck opened, the sun lighting the spray (as tests/gl/test_spray.cpp).
    scene.sky.clouds.cover = 0.0;
    return scene;
}

// Seen from above, 30 m over the bow, the bow up the image.
Camera overTheBow(const Scene& scene)
{
    const glm::dvec3 boat = scene.objects.at(0).position_m;
    Camera c;
    c.position_m = boat + 3.0 * kHeading + glm::dvec3(0.0, 30.0, 0.0);
    c.yaw_deg = std::atan2(kHeading.x, -kHeading.z) * 180.0 / 3.14159265358979;
    c.pitch_deg = -89.0;
    c.fovY_deg = 50.0;
    c.far_m = 5000.0;
    return c;
}

Image still(const Scene& scene, const Camera& camera, double time_s = kBowSprayTime_s)
{
    Renderer renderer(scene);
    return renderer.renderImage(camera, time_s, kBowSpraySize);
}

glm::dvec2 toPixel(const Camera& camera, glm::dvec3 p)
{
    const glm::dmat4 viewProj =
        camera.projection(double(kBowSpraySize.x) / kBowSpraySize.y) * camera.viewRelativeTo(camera.position_m);
    const glm::dvec4 c = viewProj * glm::dvec4(p - camera.position_m, 1.0);
    return {(c.x / c.w + 1.0) * 0.5 * kBowSpraySize.x, (1.0 - c.y / c.w) * 0.5 * kBowSpraySize.y};
}

// What the spray added: pixels changed and lighter, and the brightness it
// added to either side of the hull's centreline in the image (looking
// along its heading), its centroid, and how far ahead of the stem the
// farthest lighter pixel lies (m, along the hull in the image).
struct Added {
    int pixels = 0, lighter = 0;
    double left = 0.0, right = 0.0;
    glm::dvec2 centroid{0.0};
    double aheadOfStem_m = -1e9;
};

Added addedBy(const Image& off, const Image& on, glm::dvec2 stem, glm::dvec2 stern, double length_m = 1.0)
{
    Added a;
    double sum = 0.0;
    const glm::dvec2 along = glm::normalize(stem - stern);
    const double pixelsPerMetre = glm::length(stem - stern) / length_m;
    for (int y = 0; y < off.height; ++y)
        for (int x = 0; x < off.width; ++x) {
            const std::uint8_t *p = off.pixel(x, y), *q = on.pixel(x, y);
            if (p[0] == q[0] && p[1] == q[1] && p[2] == q[2])
                continue;
            ++a.pixels;
            const double added = double(q[0] + q[1] + q[2]) - double(p[0] + p[1] + p[2]);
            if (added <= 0.0)
                continue;
            ++a.lighter;
            const glm::dvec2 pixel(x + 0.5, y + 0.5);
            sum += added;
            a.centroid += added * pixel;
            // Image y runs down: the cross product's sign is the side.
            const glm::dvec2 d = pixel - stern;
            (along.x * d.y - along.y * d.x < 0.0 ? a.left : a.right) += added;
            a.aheadOfStem_m = std::max(a.aheadOfStem_m, glm::dot(pixel - stem, along) / pixelsPerMetre);
        }
    a.centroid /= std::max(sum, 1e-9);
    return a;
}

// The preset's boat seen from above with the wind blowing towards
// `windTowards_deg` (from +x towards +z): what the bow's spray added, and
// on which side of the centreline the wind blows to (-1 left, 1 right).
struct FromAbove {
    Added added;
    glm::dvec2 stem{0.0}, stern{0.0};
    int leeSide = 0;
};

FromAbove fromAbove(double windTowards_deg)
{
    Scene off = gale(18.0, false, 5.0), on = gale(18.0, true, 5.0);
    off.sea.wind->windDirection_deg = on.sea.wind->windDirection_deg = windTowards_deg;
    const Camera camera = overTheBow(on);
    const glm::dvec3 boat = on.objects.at(0).position_m;
    // The built-in boat's stem and transom on the water, 3.2 m forward and
    // 3.1 m aft of its origin (tests/cpu/test_bow_spray.cpp: 6.33 m).
    FromAbove r;
    r.stem = toPixel(camera, boat + 3.2 * kHeading);
    r.stern = toPixel(camera, boat - 3.1 * kHeading);
    r.added = addedBy(still(off, camera), still(on, camera), r.stem, r.stern, 6.3);
    const double windRad = windTowards_deg * 3.14159265358979 / 180.0;
    const glm::dvec2 downwind =
        toPixel(camera, boat + glm::dvec3(std::cos(windRad), 0.0, std::sin(windRad))) - toPixel(camera, boat);
    const glm::dvec2 along = r.stem - r.stern;
    r.leeSide = along.x * downwind.y - along.y * downwind.x < 0.0 ? -1 : 1;
    const Added& a = r.added;
    std::printf("wind towards %.0f deg: %d pixels changed, %d lighter; brightness added %.0f left, %.0f right "
                "(lee: %s); centroid %.1f px aft of the stem; the farthest %.2f m ahead of it\n",
                windTowards_deg, a.pixels, a.lighter, a.left, a.right, r.leeSide < 0 ? "left" : "right",
                glm::dot(a.centroid - r.stem, glm::normalize(r.stern - r.stem)), a.aheadOfStem_m);
    return r;
}

// Off the boat's lee bow, keeping pace with it at time_s: 5 m out and 4 m
// ahead of its origin, 2 m up, looking at its stem.
Camera offTheBow(const Scene& scene, double time_s)
{
    const glm::dvec3 boat = scene.objects.at(0).position_m + scene.objects.at(0).velocity_m_per_s * time_s;
    const glm::dvec3 out(-kHeading.z, 0.0, kHeading.x);
    Camera c;
    c.position_m = boat + 4.0 * kHeading + 5.0 * out + glm::dvec3(0.0, 2.0, 0.0);
    const glm::dvec3 look = boat + 2.0 * kHeading + glm::dvec3(0.0, 0.6, 0.0) - c.position_m;
    c.yaw_deg = std::atan2(look.x, -look.z) * 180.0 / 3.14159265358979;
    c.pitch_deg = std::atan2(look.y, std::hypot(look.x, look.z)) * 180.0 / 3.14159265358979;
    c.fovY_deg = 50.0;
    c.far_m = 5000.0;
    return c;
}

// Early in a slam in the preset (no wake, no crest foam): its bow plunges
// into a wave from about 0.3 s (the spray's white water in offTheBow's
// frame grows from 0.3 s to its peak at 0.5 s, 476 pixels, and is gone by
// 0.9 s, measured every 0.1 s from 0.3 to 2 s). Before the water under a
// body was sampled without aliasing (issue 47) the boat, kicked by the
// aliased short waves, met it later and harder: its white water grew from
// 0.4 s to a peak at 0.8 s and was 671 pixels at 0.6 s, where 396 are now.
constexpr double kSlam_s = 0.5;

// White water the spray laid over the frame within radius_px of a pixel:
// how many pixels it made lighter by at least `by` (of 255, the mean of
// the channels) to at least `atLeast`.
int whiteWaterNear(const Image& off, const Image& on, glm::dvec2 at, double radius_px, int by, int atLeast)
{
    int n = 0;
    for (int y = 0; y < off.height; ++y)
        for (int x = 0; x < off.width; ++x) {
            if (glm::length(glm::dvec2(x + 0.5, y + 0.5) - at) > radius_px)
                continue;
            const std::uint8_t *p = off.pixel(x, y), *q = on.pixel(x, y);
            const int before = (p[0] + p[1] + p[2]) / 3, after = (q[0] + q[1] + q[2]) / 3;
            n += after - before >= by && after >= atLeast;
        }
    return n;
}

// At a slam the bow bursts into sheets of white water at once: seen from
// off its lee bow, the spray lays bright white (at least 60 of 255
// lighter, to at least 150) over the frame about the stem, from the sheet
// pieces (spray_streaks.comp), not a faint veil of streaks blown aft that shows
// only once its drops have flown. Measured at 320 x 180: 676 such pixels
// in the disc 2 m about the stem; the drops alone (before the sheet
// pieces, main at 17d8988) 226.
TEST_F(BowSpray, ASlamThrowsWhiteSheetsAboutTheStem)
{
    const Scene off = gale(18.0, false, 5.0), on = gale(18.0, true, 5.0);
    const Camera camera = offTheBow(on, kSlam_s);
    const glm::dvec3 boat = on.objects.at(0).position_m + on.objects.at(0).velocity_m_per_s * kSlam_s;
    const glm::dvec2 stem = toPixel(camera, boat + 3.2 * kHeading + glm::dvec3(0.0, 0.5, 0.0));
    // 2 m about the stem, in pixels at its distance.
    const double radius_px = glm::length(toPixel(camera, boat + 5.2 * kHeading + glm::dvec3(0.0, 0.5, 0.0)) - stem);
    const Image i0 = still(off, camera, kSlam_s), i1 = still(on, camera, kSlam_s);
    const int white = whiteWaterNear(i0, i1, stem, radius_px, 60, 150);
    const int disc = int(3.14159 * radius_px * radius_px);
    std::printf("stem at (%.1f, %.1f), %.1f px for 2 m: %d of %d pixels white water\n", stem.x, stem.y, radius_px,
                white, disc);
    EXPECT_GT(white, 450) << "no sheet of white water about the stem early in a slam";
}

TEST_F(BowSpray, NoneBelowBeaufortSeven)
{
    // 13.8 m/s: Beaufort 6, just below 7's 13.9; the sea with its crests.
    const Scene off = gale(13.8, false, 5.0, true), on = gale(13.8, true, 5.0, true);
    const Camera camera = overTheBow(on);
    const Added a = addedBy(still(off, camera), still(on, camera), {0.0, 0.0}, {1.0, 0.0});
    EXPECT_EQ(a.pixels, 0) << "spray drawn below Beaufort 7 from a hull under way";
}

TEST_F(BowSpray, NoneFromAHullAtRest)
{
    const Scene restOff = gale(18.0, false, 0.0), restOn = gale(18.0, true, 0.0);
    const Camera camera = overTheBow(restOn);
    const Added rest = addedBy(still(restOff, camera), still(restOn, camera), {0.0, 0.0}, {1.0, 0.0});
    EXPECT_EQ(rest.pixels, 0) << "spray from a hull at rest (or crest spray on a sea without foam)";
    // The control: the same hull under way throws some.
    const Scene wayOff = gale(18.0, false, 5.0), wayOn = gale(18.0, true, 5.0);
    const Added way = addedBy(still(wayOff, camera), still(wayOn, camera), {0.0, 0.0}, {1.0, 0.0});
    EXPECT_GT(way.pixels, 100) << "no spray from the hull under way either";
}

// Seen from above, the wind from dead ahead: white water from both sides
// of the bow alike, none thrown far ahead of the stem, carried aft.
TEST_F(BowSpray, SheetsFromBothSidesOfTheBowInAHeadWind)
{
    const double heading_deg = std::atan2(kHeading.z, kHeading.x) * 180.0 / 3.14159265358979;
    const FromAbove r = fromAbove(heading_deg + 180.0);
    const Added& a = r.added;
    EXPECT_GT(a.pixels, kBowSpraySize.x * kBowSpraySize.y / 200) << "too little spray from a bow at 5 m/s in a gale";
    EXPECT_GT(a.lighter, a.pixels * 9 / 10) << "bow spray is white water over a dark sea";
    EXPECT_GT(a.left, 0.3 * (a.left + a.right)) << "too little spray on the bow's left";
    EXPECT_GT(a.right, 0.3 * (a.left + a.right)) << "too little spray on the bow's right";
    EXPECT_LT(a.aheadOfStem_m, 1.5) << "spray thrown far ahead of the stem";
    EXPECT_GT(glm::dot(a.centroid - r.stem, glm::normalize(r.stern - r.stem)), 0.0)
        << "the head wind does not carry the spray aft";
}

// The wind from abeam carries the bow's spray to leeward.
TEST_F(BowSpray, CarriedToLeewardInACrossWind)
{
    const double heading_deg = std::atan2(kHeading.z, kHeading.x) * 180.0 / 3.14159265358979;
    for (const double across_deg : {90.0, -90.0}) {
        const FromAbove r = fromAbove(heading_deg + across_deg);
        const double lee = r.leeSide < 0 ? r.added.left : r.added.right;
        const double windward = r.leeSide < 0 ? r.added.right : r.added.left;
        EXPECT_GT(lee, 2.0 * windward) << "the wind towards " << heading_deg + across_deg << " deg";
    }
}

TEST_F(BowSpray, StillsReproduceBitForBitWhateverCameBefore)
{
    const Scene scene = gale(18.0, true, 5.0);
    const Camera camera = overTheBow(scene);
    const Image first = still(scene, camera), second = still(scene, camera);
    EXPECT_TRUE(first.rgba == second.rgba) << "two stills of the same time differ";
    // Frames before it, a later one included (the bodies start again),
    // the last two seconds before it (the bodies step on from there).
    Renderer sequence(scene);
    for (const double t : {-4.0, 2.5, -2.0})
        sequence.renderImage(camera, t, kBowSpraySize);
    const Image arrived = sequence.renderImage(camera, kBowSprayTime_s, kBowSpraySize);
    EXPECT_TRUE(first.rgba == arrived.rgba) << "the frame depends on the frames before it";
}

} // namespace
