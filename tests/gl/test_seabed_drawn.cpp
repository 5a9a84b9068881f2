// The seabed drawn (docs/RENDERING.md "The seabed"): a beach ahead of the
// camera shows as land where the open sea was, one draw call more a pass;
// a host's heights join the floor the renderer holds, are refused when
// malformed (nothing changed), and are not drawn.
#include "support/gl_test.h"
#include "swell/debug.h"
#include "swell/error.h"
#include "swell/flat_model.h"
#include "swell/renderer.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace {

using namespace swell;

class SeabedDrawn : public test::GlTest {};

constexpr glm::ivec2 kSeabedDrawnSize{160, 90};
constexpr double kSeabedDrawnTime_s = 4.0;

// The open sea, no island, no objects; the camera 40 m up looking -z,
// down at the water ahead.
Scene seabedDrawnOpenSea()
{
    Scene scene = defaultScene();
    scene.objects.clear();
    scene.showTerrain = false;
    scene.camera.position_m = {0.0, 40.0, 0.0};
    scene.camera.yaw_deg = 0.0;
    scene.camera.pitch_deg = -25.0;
    scene.camera.path.clear();
    return scene;
}

// Pixels of land: sand, lit and veiled by the haze, is grey to warm
// (blue no more than red), where the sea and the sky are blue (blue 15 to
// 60 above red); the sun's glitter, white, is left out by its brightness.
int landPixels(const Image& image)
{
    int count = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = image.pixel(x, y);
            count += int(p[2]) <= int(p[0]) + 8 && p[0] < 220 ? 1 : 0;
        }
    return count;
}

TEST_F(SeabedDrawn, ABeachAheadIsDrawnAsLand)
{
    Scene scene = seabedDrawnOpenSea();
    Renderer sea(scene);
    const Camera camera = cameraAt(scene.camera, kSeabedDrawnTime_s);
    sea.renderImage(camera, kSeabedDrawnTime_s, kSeabedDrawnSize); // the first frame's own work done
    const Image before = sea.renderImage(camera, kSeabedDrawnTime_s, kSeabedDrawnSize);
    const int callsBefore = sea.counters().drawCalls;

    // The land 100 m ahead, rising away from the camera (the beach faces +z).
    scene.seabed.beaches.push_back(SeabedBeach{.shorePoint_m = {0.0, -100.0}, .seawardAzimuth_deg = 180.0,
                                               .slope = 0.05, .length_m = 2000.0, .top_m = 8.0, .landWidth_m = 400.0});
    sea.setScene(scene);
    sea.renderImage(camera, kSeabedDrawnTime_s, kSeabedDrawnSize);
    const Image after = sea.renderImage(camera, kSeabedDrawnTime_s, kSeabedDrawnSize);
    EXPECT_LT(landPixels(before), kSeabedDrawnSize.x * kSeabedDrawnSize.y / 100);
    EXPECT_GT(landPixels(after), kSeabedDrawnSize.x * kSeabedDrawnSize.y / 10);
    // One draw call more in each pass that draws the world.
    EXPECT_GT(sea.counters().drawCalls, callsBefore);
    EXPECT_NEAR(sea.seabed().elevation_m({0.0, -200.0}), 5.0, 1e-9);

    // What a fresh renderer draws for the scene is what the change drew.
    Renderer fresh(scene);
    fresh.renderImage(camera, kSeabedDrawnTime_s, kSeabedDrawnSize);
    EXPECT_TRUE(fresh.renderImage(camera, kSeabedDrawnTime_s, kSeabedDrawnSize).rgba == after.rgba);
}

TEST_F(SeabedDrawn, HostHeightsJoinTheFloorUndrawn)
{
    const Scene scene = seabedDrawnOpenSea();
    Renderer renderer(scene);
    // Flat water while the picture is compared: the host's floor is not
    // drawn, but the scene's waves feel it (checked below).
    renderer.setWaveModel(std::make_shared<FlatModel>());
    const Camera camera = cameraAt(scene.camera, kSeabedDrawnTime_s);
    const Image before = renderer.renderImage(camera, kSeabedDrawnTime_s, kSeabedDrawnSize);
    EXPECT_EQ(renderer.seabed().elevation_m({0.0, -50.0}), -std::numeric_limits<double>::infinity());

    SeabedHeights heights{.columns = 2, .rows = 2, .heights_m = {-4.0f, -4.0f, -2.0f, -2.0f}, .min_m = {-100.0, -100.0},
                          .max_m = {100.0, 0.0}};
    SeabedHeights wrong = heights;
    wrong.heights_m.push_back(1.0f);
    EXPECT_THROW(renderer.setSeabedHeights(wrong), Error);
    SeabedHeights nan = heights;
    nan.heights_m[1] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW(renderer.setSeabedHeights(nan), Error);
    EXPECT_EQ(renderer.seabed().elevation_m({0.0, -50.0}), -std::numeric_limits<double>::infinity());

    renderer.setSeabedHeights(heights);
    EXPECT_NEAR(renderer.seabed().elevation_m({0.0, -50.0}), -3.0, 1e-9);
    EXPECT_TRUE(renderer.renderImage(camera, kSeabedDrawnTime_s, kSeabedDrawnSize).rgba == before.rgba);
    // The scene's Gerstner waves run over the host's floor: in 3 m of
    // water they are no longer the open sea's.
    renderer.setWaveModel(nullptr);
    const Renderer open(scene);
    double largest = 0.0;
    for (double t = 0.0; t < 8.0; t += 0.5)
        largest = std::max(largest, std::abs(renderer.waveModel().heightAt({0.0, -50.0}, t)
                                             - open.waveModel().heightAt({0.0, -50.0}, t)));
    EXPECT_GT(largest, 0.01);
    renderer.clearSeabedHeights();
    EXPECT_EQ(renderer.seabed().elevation_m({0.0, -50.0}), -std::numeric_limits<double>::infinity());
}

// The spectral model feels the host's floor as the scene's, when the heights
// are set and when a scene change builds the model again: over 1 m of the
// host's water the breaking cut holds the sea under the depth.
TEST_F(SeabedDrawn, HostHeightsReachTheSpectralSea)
{
    Scene scene = seabedDrawnOpenSea();
    scene.waves.model = WaveModelKind::Spectral;
    scene.sea.wind->windSpeed_mps = 16.0;
    Renderer renderer(scene);
    const Renderer open(scene);
    renderer.setSeabedHeights(SeabedHeights{.columns = 2, .rows = 2, .heights_m = {-1.0f, -1.0f, -1.0f, -1.0f},
                                            .min_m = {-300.0, -300.0}, .max_m = {300.0, 300.0}});
    double largest = 0.0, openLargest = 0.0;
    for (double t = 0.0; t < 8.0; t += 0.5) {
        largest = std::max(largest, std::abs(renderer.waveModel().heightAt({0.0, 0.0}, t)));
        openLargest = std::max(openLargest, std::abs(open.waveModel().heightAt({0.0, 0.0}, t)));
    }
    // A 16 m/s sea stands metres high; over 1 m of water the cut holds it
    // under 0.78 of the depth.
    EXPECT_GT(openLargest, 1.0);
    EXPECT_LT(largest, 0.78);
    // And the model a scene change builds again feels it as well.
    scene.sea.wind->seed += 1;
    renderer.setScene(scene);
    largest = 0.0;
    for (double t = 0.0; t < 8.0; t += 0.5)
        largest = std::max(largest, std::abs(renderer.waveModel().heightAt({0.0, 0.0}, t)));
    EXPECT_LT(largest, 0.78) << "after setScene";
}

} // namespace

