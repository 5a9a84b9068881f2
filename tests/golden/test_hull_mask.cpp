// Pass 3's clean intersections: seen from above, no water shows inside the
// floating boat's hull, because the hull's closed volume is drawn into depth
// before the water. The built-in boat has a deck 0.3 m above its waterline,
// so the mechanism is tested on its open shell alone (the node "hull skin"
// of assets/models/boat.gltf: no deck, no wheelhouse). The control is that
// shell as a user glTF model without a hull volume: there the water does
// show, so the check finds water where there is some.
#include "assets/mesh_data.h"
#include "support/camera_rays.h"
#include "support/gl_test.h"
#include "support/gltf_writer.h"
#include "support/golden.h"
#include "swell/debug.h"
#include "swell/renderer.h"

#include <cmath>
#include <filesystem>

namespace {

class HullMask : public swell::test::GlTest {};

constexpr glm::ivec2 kHullMaskSize{320, 240};
constexpr double kHullMaskTime_s = 7.0;
const std::filesystem::path kBoatFile = std::filesystem::path(SWELL_SOURCE_DIR) / "assets" / "models" / "boat.gltf";
// The built-in boat's opening (assets/models/boat_model.py): its sheer lies
// 0.78 m above its origin at the transom (x = -3.5 m) and rises forward; from
// the transom to 1.5 m ahead of midships its half-breadth is over 0.99 m.
// The test's region lies well inside that: rays that cross y = 0.85 m there.
constexpr double kOpeningHeight_m = 0.85;
constexpr double kOpeningAft_m = -3.2, kOpeningFore_m = 1.3, kOpeningHalfWidth_m = 0.7;

// The boat's open shell: its outer skin and transom, nothing inside.
swell::detail::MeshData openShell() { return swell::detail::loadGltf(kBoatFile, "hull skin").hull; }

// A floating boat in wind waves, the camera 12 m above it looking down. The
// water is painted a green no hull or sky has (deep colour pure green, light
// absorbed within centimetres, no sun glitter), so water pixels are easy to tell.
swell::Scene boatFromAbove(const std::string& boatPath)
{
    swell::Scene scene = swell::defaultScene();
    scene.showTerrain = false;
    scene.fog.start_m = 1.0e5;
    scene.fog.end_m = 2.0e5;
    scene.sun.intensity = 0.0;
    scene.water.deepColor = {0.0, 1.0, 0.0};
    scene.water.absorption_per_m = {50.0, 50.0, 50.0};
    scene.objects = {{boatPath, {0.0, 0.0, 0.0}, 0.0, 1.0, true}};
    scene.camera.position_m = {0.0, 12.0, 0.5};
    scene.camera.pitch_deg = -85.0;
    return scene;
}

bool isWaterGreen(const std::uint8_t* p) { return p[1] > p[0] + 80 && p[1] > p[2] + 80; }

struct Count {
    int inside = 0, water = 0;
};

// Water-green pixels among those whose ray crosses the opening's plane in
// the region inside the sheer: rays that enter the open hull. The boat's tilt
// (at most half the wave slope, a few degrees here) moves the sheer by
// centimetres; the margins are 0.3 m.
Count waterInsideHull(const swell::Renderer& renderer, const swell::Camera& camera, const swell::Image& image)
{
    const double openingY = renderer.waveModel().heightAt({0.0, 0.0}, kHullMaskTime_s) + kOpeningHeight_m;
    Count count;
    for (int y = 0; y < kHullMaskSize.y; ++y)
        for (int x = 0; x < kHullMaskSize.x; ++x) {
            const glm::dvec3 d = swell::test::pixelRay(camera, kHullMaskSize, x, y);
            const glm::dvec3 p = camera.position_m + d * ((openingY - camera.position_m.y) / d.y);
            if (p.x < kOpeningAft_m || p.x > kOpeningFore_m || std::abs(p.z) > kOpeningHalfWidth_m)
                continue;
            ++count.inside;
            count.water += isWaterGreen(image.pixel(x, y));
        }
    return count;
}

TEST_F(HullMask, NoWaterInsideTheFloatingBuiltinBoat)
{
    const swell::Scene scene = boatFromAbove("builtin:boat");
    swell::Renderer renderer(scene);
    const swell::Camera camera = swell::cameraAt(scene.camera, kHullMaskTime_s);
    const swell::Image image = renderer.renderImage(camera, kHullMaskTime_s, kHullMaskSize);
    const std::string path = swell::test::saveTestImage(image, "hull_mask_builtin_boat");
    // The water outside is green, or the colour test means nothing.
    EXPECT_TRUE(isWaterGreen(image.pixel(8, 8))) << path;
    const Count c = waterInsideHull(renderer, camera, image);
    // The region is about 90 x 28 pixels here.
    EXPECT_GT(c.inside, 1000) << "the hull opening is not where the test expects it: " << path;
    EXPECT_EQ(c.water, 0) << "water shows inside the hull: " << path;
}

TEST_F(HullMask, WaterShowsInsideTheOpenShellWithoutAVolume)
{
    const std::filesystem::path folder = std::filesystem::path(SWELL_TEST_OUTPUT_DIR) / "hull_mask";
    std::filesystem::create_directories(folder);
    swell::test::writeGltf(openShell(), folder / "open_boat.gltf");
    swell::Scene scene = boatFromAbove("open_boat.gltf");
    scene.assetFolder = folder.string();
    swell::Renderer renderer(scene);
    // The water the unmasked shell shows inside it lies within a metre of
    // its sides, where the contact foam (docs/RENDERING.md "Foam where water
    // meets what stands in it") would lay its band over it: left out, as
    // this control asks whether the water is drawn there, not what is on it.
    swell::RendererTesting::setContactFoam(renderer, false);
    const swell::Camera camera = swell::cameraAt(scene.camera, kHullMaskTime_s);
    const swell::Image image = renderer.renderImage(camera, kHullMaskTime_s, kHullMaskSize);
    const std::string path = swell::test::saveTestImage(image, "hull_mask_user_gltf_boat");
    const Count c = waterInsideHull(renderer, camera, image);
    // The boat floats with its origin on the water, 0.48 m above its keel, so
    // without a mask most of the opening shows water.
    EXPECT_GT(c.water, c.inside / 2) << "expected water inside an unmasked hull: " << path;
}

TEST_F(HullMask, NoWaterInsideAUserGltfBoatWithAHullNode)
{
    // The same open shell in a user's glTF file, with its closed volume as a
    // node named "Hull" (docs/SCENE.md, hull_node): masked like the built-in.
    const std::filesystem::path folder = std::filesystem::path(SWELL_TEST_OUTPUT_DIR) / "hull_mask";
    std::filesystem::create_directories(folder);
    // The volume is magenta, a colour nothing else has: it must never be seen.
    swell::detail::MeshData hull = swell::detail::makeBuiltinHullVolume("boat");
    for (swell::detail::MeshVertex& v : hull.vertices)
        v.color = {1.0f, 0.0f, 1.0f};
    swell::test::writeGltf({{"Boat", openShell()}, {"Hull", hull}}, folder / "boat_with_hull.gltf");
    swell::Scene scene = boatFromAbove("boat_with_hull.gltf");
    scene.objects[0].hullNode = "Hull";
    scene.assetFolder = folder.string();
    swell::Renderer renderer(scene);
    const swell::Camera camera = swell::cameraAt(scene.camera, kHullMaskTime_s);
    const swell::Image image = renderer.renderImage(camera, kHullMaskTime_s, kHullMaskSize);
    const std::string path = swell::test::saveTestImage(image, "hull_mask_user_gltf_hull_node");
    EXPECT_TRUE(isWaterGreen(image.pixel(8, 8))) << path;
    const Count c = waterInsideHull(renderer, camera, image);
    EXPECT_GT(c.inside, 1000) << "the hull opening is not where the test expects it: " << path;
    EXPECT_EQ(c.water, 0) << "water shows inside the hull: " << path;
    int magenta = 0;
    for (std::size_t i = 0; i < image.rgba.size(); i += 4)
        // Shaded without sun, magenta darkens to purple: red and blue well above green.
        magenta += image.rgba[i] > image.rgba[i + 1] + 30 && image.rgba[i + 2] > image.rgba[i + 1] + 60;
    EXPECT_EQ(magenta, 0) << "the hull node is drawn in colour: " << path;
}

} // namespace
