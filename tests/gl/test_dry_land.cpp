// Dry land stays dry (issue 44): from the camera of every preset with a sea
// floor (the built-in island, or [seabed] shapes), and from one 250 m up off
// the floor's shore, no pixel the labels call water lies where the floor
// stands above the sea's mean level by more than the swash reaches, at two
// times. A water pixel's place is its range along its ray (docs/LABELS.md);
// the floor's height there is swell::Seabed's, the function the island and
// the shapes are drawn from.
#include "support/gl_test.h"
#include "swell/dataset/labels.h"
#include "swell/gpu/label_classes.h"
#include "swell/renderer.h"
#include "swell/scene/scene.h"
#include "swell/scene/scene_file.h"
#include "swell/scene/seabed.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

class DryLand : public swell::test::GlTest {};

// How high above the mean level the floor under a drawn water pixel may
// stand: the coast field's samples lie 2 m or more apart (coast_grid.h) and
// its gain falls to 0 between the last wet sample and the first dry one, so
// the water may reach one sample spacing onto a beach: 5 cm on the coast
// preset's 1:40. A wave on land would stand its crest's height, up to 2 m,
// above the shore's sand. (The swash running up a beach is not drawn.)
constexpr double kShoreReach_m = 0.1;
// Beyond this range the island's levels of detail (RENDERING.md, "The
// island's levels of detail"), whose error is under a pixel on screen, may
// stand its drawn silhouette a pixel off the exact one, and either pixel the
// boundary splits may take either side: water within 2 px of another class
// is left out there.
constexpr double kIslandDetail_m = 1000.0;

// The world direction of the ray through pixel (x, y)'s centre, unit.
glm::dvec3 dryLandPixelRay(const swell::CameraCalibration& c, int x, int y)
{
    const glm::dvec3 camera((x + 0.5 - c.cx_px) / c.fx_px, (y + 0.5 - c.cy_px) / c.fy_px, 1.0);
    return glm::normalize(glm::dmat3(c.worldFromCamera) * camera);
}

bool besideAnotherClass(const std::vector<std::uint16_t>& semantic, glm::ivec2 size, int x, int y)
{
    const std::uint16_t own = semantic[std::size_t(y) * std::size_t(size.x) + std::size_t(x)];
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
            const int nx = std::clamp(x + dx, 0, size.x - 1), ny = std::clamp(y + dy, 0, size.y - 1);
            if (semantic[std::size_t(ny) * std::size_t(size.x) + std::size_t(nx)] != own)
                return true;
        }
    return false;
}

struct Wet {
    int waterPixels = 0;
    int onLand = 0;         // water pixels where the floor stands above the swash
    double highest_m = -1e9; // the highest floor under a water pixel, above the mean level
};

Wet waterOverLand(swell::Renderer& renderer, const swell::Seabed& seabed, const swell::Camera& camera, double time_s)
{
    const glm::ivec2 size(256, 144);
    renderer.renderImage(camera, time_s, size);
    const swell::FrameLabels labels = renderer.renderLabels(camera, size);
    Wet wet;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(size.x) + std::size_t(x);
            if (labels.semantic[i] != SWELL_LABEL_WATER || !(labels.range_m[i] < 1.0e4))
                continue;
            if (labels.range_m[i] > kIslandDetail_m && besideAnotherClass(labels.semantic, size, x, y))
                continue;
            ++wet.waterPixels;
            const glm::dvec3 p = camera.position_m + double(labels.range_m[i]) * dryLandPixelRay(labels.camera, x, y);
            const double floor_m = seabed.elevation_m({p.x, p.z});
            wet.highest_m = std::max(wet.highest_m, floor_m);
            if (floor_m > kShoreReach_m) {
                ++wet.onLand;
            }
        }
    return wet;
}

TEST_F(DryLand, NoPresetDrawsWaterOnLandAboveTheSwash)
{
    int scenesWithLand = 0;
    for (const auto& entry : fs::directory_iterator(fs::path(SWELL_SOURCE_DIR) / "scenes")) {
        if (entry.path().extension() != ".toml")
            continue;
        const swell::Scene scene = swell::loadScene(entry.path());
        const swell::Seabed seabed(scene);
        const std::optional<swell::SeabedExtent> extent = seabed.extent();
        if (!extent || scene.camera.position_m.y < scene.sea.level_m)
            continue;
        ++scenesWithLand;
        SCOPED_TRACE(entry.path().filename().string());
        swell::Renderer renderer(scene);
        std::vector<swell::Camera> cameras{swell::cameraAt(scene.camera, 0.0)};
        // 250 m up, 300 m off the floor's southern edge (+z), looking north
        // at its shore.
        swell::Camera above = cameras.front();
        above.position_m = {0.5 * (extent->min_m.x + extent->max_m.x), scene.sea.level_m + 250.0, extent->max_m.y + 300.0};
        above.yaw_deg = 0.0;
        above.pitch_deg = -35.0;
        above.roll_deg = 0.0;
        cameras.push_back(above);
        // Time outermost: the bodies' history runs forward once (0 to 5 to
        // 20 s) for both cameras, where a camera outermost would step it
        // from 0 again for the second.
        for (const double t : {5.0, 20.0})
            for (const swell::Camera& camera : cameras) {
                const Wet wet = waterOverLand(renderer, seabed, camera, t);
                EXPECT_GT(wet.waterPixels, 100) << "t = " << t;
                EXPECT_EQ(wet.onLand, 0) << "t = " << t << ": water over land up to " << wet.highest_m << " m";
            }
    }
    EXPECT_GE(scenesWithLand, 6);
}

// The labels' shoreline (swell::measureShoreline) lies where the drawn
// water meets the floor: from the coast preset's camera, each chain's water
// points stand where the beach is within 0.3 m of the sea's mean level (the
// waves are cut to nearly nothing at the waterline) plus the height of the
// beach a pixel spans there (hundreds of metres of ground at a grazing
// 1.5 degrees, 1.5 km off).
TEST_F(DryLand, TheShorelineLiesWhereTheWaterMeetsTheBeach)
{
    const swell::Scene scene = swell::loadScene(fs::path(SWELL_SOURCE_DIR) / "scenes" / "coast.toml");
    const swell::Seabed seabed(scene);
    swell::Renderer renderer(scene);
    const swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    const glm::ivec2 size(256, 144);
    renderer.renderImage(camera, 20.0, size);
    const swell::FrameLabels labels = renderer.renderLabels(camera, size);
    std::size_t corners = 0, beach = 0, offShore = 0;
    for (const swell::ShoreLine& line : labels.shoreline)
        for (const glm::dvec3& p : line.points_m) {
            ++corners;
            const double floor_m = seabed.elevation_m({p.x, p.z});
            // Behind the preset's 400 m strip of land the floor drops to the
            // open sea's: water meets the strip's back there, no beach.
            if (std::isinf(floor_m))
                continue;
            ++beach;
            // A pixel's footprint along the beach: its angle times the range,
            // over the sine of the grazing angle; up the preset's 1:40
            // slope, that much height.
            const double range_m = glm::length(p - camera.position_m);
            const double grazing = (camera.position_m.y - p.y) / range_m;
            const double footprint_m = range_m / labels.camera.fy_px / grazing;
            if (!(std::abs(floor_m) < 0.3 + footprint_m * scene.seabed.beaches.front().slope))
                ++offShore;
        }
    // The beach's waterline crosses the view: a long chain of corners.
    EXPECT_GT(beach, 100u) << "of " << corners;
    EXPECT_EQ(offShore, 0u) << "of " << beach;
}

} // namespace

