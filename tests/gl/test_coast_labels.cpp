// The shore's own label classes (issue 44, item 5; docs/LABELS.md): from
// the coast preset's camera, the surf's whitewater is `surf` and only in the
// surf zone, and the beach the swash wets is `wet_sand` and only up to where
// the drawn sand is half darkened, with the dry sand above it `terrain`.
// Each pixel's point is its range along its centre ray; the floor there is
// swell::Seabed's, the function the beach is drawn from.
#include "ocean/coast/swash.h"
#include "support/gl_test.h"
#include "swell/dataset/labels.h"
#include "swell/gpu/label_classes.h"
#include "swell/renderer.h"
#include "swell/scene/scene.h"
#include "swell/scene/scene_file.h"
#include "swell/scene/seabed.h"
#include "swell/wave_model.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

class CoastLabels : public swell::test::GlTest {};

// The world direction of the ray through pixel (x, y)'s centre, unit.
glm::dvec3 coastLabelsPixelRay(const swell::CameraCalibration& c, int x, int y)
{
    const glm::dvec3 camera((x + 0.5 - c.cx_px) / c.fx_px, (y + 0.5 - c.cy_px) / c.fy_px, 1.0);
    return glm::normalize(glm::dmat3(c.worldFromCamera) * camera);
}

TEST_F(CoastLabels, SurfAndWetSandAreWhereTheShoreHasThem)
{
    const swell::Scene scene = swell::loadScene(fs::path(SWELL_SOURCE_DIR) / "scenes" / "coast.toml");
    const swell::Seabed seabed(scene);
    swell::Renderer renderer(scene);
    // The beach's wetness is 1 - smoothstep(setup, run-up, height) on its
    // 1:40 face (shaders/swash.glsl): half wet half way between the two.
    const double slope = scene.seabed.beaches.front().slope;
    // Stockdon et al.'s run-up and setup depend on H0 and L0 through their
    // product alone, which the renderer hands the shading (view_frame.cpp).
    const double h0l0_m2 = swell::coast::offshoreHeightTimesWavelength_m2(
        scene, swell::makeWaveModel(scene, seabed)->heightDeviation_m());
    const double rootH0L0_m = std::sqrt(h0l0_m2);
    const double setup_m = swell::coast::setup_m(rootH0L0_m, rootH0L0_m, slope);
    const double runUp_m = swell::coast::runUp2_m(rootH0L0_m, rootH0L0_m, slope);
    const double halfWet_m = 0.5 * (setup_m + runUp_m);
    ASSERT_GT(runUp_m, 0.5) << "the preset's swell runs up its beach";
    // The surf zone: the swell (H_s 1.8 m) breaks from about H_s / 0.59 =
    // 3 m of water (Thornton & Guza 1983, coast_field.cpp); a roller's
    // lace reaches a little further out.
    constexpr double kSurfZoneDepth_m = 5.0;

    // The preset's camera (10 m up in the surf, the beach far off) and one
    // standing 3 m up at the waterline looking up the beach, where a pixel
    // spans centimetres of its height.
    swell::CameraSettings onTheBeach = scene.camera;
    onTheBeach.position_m = {0.0, 3.0, 296.0};
    onTheBeach.yaw_deg = 180.0; // towards +z, up the beach
    onTheBeach.pitch_deg = -12.0;
    const glm::ivec2 size(256, 144);
    // Wet and dry are told apart where a pixel spans under 10 cm of the
    // beach's height: the near beach (far off, a pixel spans metres).
    constexpr double kResolvedRise_m = 0.1;
    int surf = 0, surfOffshore = 0, wetSand = 0, wetTooHigh = 0, dryBeach = 0, dryTooLow = 0;
    int resolvedWet = 0, resolvedDry = 0;
    double highestWet_m = -1e9, lowestDry_m = 1e9;
    for (const swell::CameraSettings& settings : {scene.camera, onTheBeach}) {
    const swell::Camera camera = swell::cameraAt(settings, 0.0);
    renderer.renderImage(camera, 20.0, size);
    const swell::FrameLabels labels = renderer.renderLabels(camera, size);
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(size.x) + std::size_t(x);
            const std::uint16_t s = labels.semantic[i];
            if (!std::isfinite(labels.range_m[i]))
                continue;
            const glm::dvec3 p = camera.position_m + double(labels.range_m[i]) * coastLabelsPixelRay(labels.camera, x, y);
            const double floor_m = seabed.elevation_m({p.x, p.z});
            // The height a pixel's footprint spans up the beach at its
            // grazing angle: a pixel on the boundary may lie either side.
            const double range_m = double(labels.range_m[i]);
            const double grazing = std::max((camera.position_m.y - p.y) / range_m, 1e-3);
            const double footprintRise_m = range_m / labels.camera.fy_px / grazing * slope;
            if (s == SWELL_LABEL_SURF) {
                ++surf;
                surfOffshore += !(floor_m > -kSurfZoneDepth_m);
            } else if (s == SWELL_LABEL_WET_SAND) {
                ++wetSand;
                wetTooHigh += p.y > halfWet_m + footprintRise_m + 0.02;
                if (footprintRise_m < kResolvedRise_m) {
                    ++resolvedWet;
                    highestWet_m = std::max(highestWet_m, p.y);
                }
            } else if (s == SWELL_LABEL_TERRAIN && std::isfinite(floor_m) && labels.normal[i].y > 0.99) {
                // The beach's face (1:40), not the strip's back or its sides.
                ++dryBeach;
                dryTooLow += p.y < halfWet_m - footprintRise_m - 0.02;
                if (footprintRise_m < kResolvedRise_m) {
                    ++resolvedDry;
                    lowestDry_m = std::min(lowestDry_m, p.y);
                }
            }
        }
    }
    std::printf("surf %d pixels (%d offshore); wet sand %d (%d near, up to %.2f m), dry beach %d (%d near, from "
                "%.2f m); half wet at %.2f m (setup %.2f, run-up %.2f)\n",
                surf, surfOffshore, wetSand, resolvedWet, highestWet_m, dryBeach, resolvedDry, lowestDry_m, halfWet_m,
                setup_m, runUp_m);
    EXPECT_GT(surf, 200) << "the breaking swell's whitewater is labelled surf";
    EXPECT_EQ(surfOffshore, 0) << "surf past " << kSurfZoneDepth_m << " m of water";
    EXPECT_GT(wetSand, 200) << "the swash's band of wet sand is labelled";
    EXPECT_EQ(wetTooHigh, 0) << "wet sand above the half-wet line";
    EXPECT_GT(dryBeach, 200) << "the dry beach above it is terrain";
    EXPECT_EQ(dryTooLow, 0) << "dry sand below the half-wet line";
    EXPECT_GT(resolvedWet, 50) << "near wet sand, where a pixel spans under " << kResolvedRise_m << " m";
    EXPECT_GT(resolvedDry, 50) << "near dry sand, where a pixel spans under " << kResolvedRise_m << " m";
    // From under the sea (a diver 1.2 m down over 2.5 m of water, looking at the
    // beach's slope) the floor below the still level is under the water,
    // not bared sand: terrain.
    swell::CameraSettings diver = onTheBeach;
    diver.position_m = {0.0, -1.2, 200.0};
    diver.pitch_deg = -10.0;
    const swell::Camera below = swell::cameraAt(diver, 0.0);
    renderer.renderImage(below, 20.0, size);
    const swell::FrameLabels underwater = renderer.renderLabels(below, size);
    int floorSeen = 0, floorCalledWet = 0;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(size.x) + std::size_t(x);
            const std::uint16_t s = underwater.semantic[i];
            if (!swell::isGroundClass(s) || !std::isfinite(underwater.range_m[i]))
                continue;
            const glm::dvec3 p = below.position_m + double(underwater.range_m[i]) * coastLabelsPixelRay(underwater.camera, x, y);
            if (p.y >= -0.05)
                continue;
            ++floorSeen;
            floorCalledWet += s == SWELL_LABEL_WET_SAND;
        }
    std::printf("from 1.2 m under the sea: %d pixels of floor below the still level, %d called wet sand\n", floorSeen,
                floorCalledWet);
    EXPECT_GT(floorSeen, 1000) << "the diver sees the floor";
    EXPECT_EQ(floorCalledWet, 0) << "of " << floorSeen << " pixels of floor under the water";
    // The classes have their names.
    const std::vector<std::string> classes = swell::labelClassesOf(scene);
    EXPECT_EQ(classes[SWELL_LABEL_SURF], "surf");
    EXPECT_EQ(classes[SWELL_LABEL_WET_SAND], "wet_sand");
}

} // namespace
