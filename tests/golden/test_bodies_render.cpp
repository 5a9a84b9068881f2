// Floating rigid bodies in rendered frames: the same scene and time give the
// same image bit for bit, whether the renderer got there in one frame (as
// `swell render --time T` does) or through many uneven frames (as the viewer
// does), and the bodies do take part (the image differs from the same scene
// whose objects merely sit on the surface).
#include "assets/mesh_data.h"
#include "support/gl_test.h"
#include "support/gltf_writer.h"
#include "support/golden.h"
#include "swell/error.h"
#include "swell/renderer.h"

#include <cmath>
#include <filesystem>

namespace {

class BodiesRender : public swell::test::GlTest {};

constexpr glm::ivec2 kBodiesRenderSize{256, 144};
constexpr double kBodiesRenderTime_s = 6.5;

// The built-in boat as a rigid body under way, dropped 0.3 m so it heaves,
// and a ballasted buoy, seen from 14 m off.
swell::Scene bodiesScene()
{
    swell::Scene scene = swell::defaultScene();
    scene.showTerrain = false;
    swell::SceneObject boat;
    boat.path = "builtin:boat";
    boat.position_m = {0.0, 0.3, -14.0};
    boat.yaw_deg = 30.0;
    boat.floats = true;
    boat.density_kg_per_m3 = 250.0;
    boat.velocity_m_per_s = {0.3, 0.0, 0.0};
    swell::SceneObject buoy;
    buoy.path = "builtin:buoy";
    buoy.position_m = {5.0, 0.0, -18.0};
    buoy.floats = true;
    buoy.density_kg_per_m3 = 400.0;
    buoy.centerOfMassOffset_m = {0.0, -0.9, 0.0};
    scene.objects = {boat, buoy};
    scene.camera.position_m = {0.0, 3.0, 0.0};
    scene.camera.pitch_deg = -10.0;
    return scene;
}

TEST_F(BodiesRender, SameTimeSameImageHoweverTheFramesFell)
{
    const swell::Scene scene = bodiesScene();
    const swell::Camera camera = swell::cameraAt(scene.camera, kBodiesRenderTime_s);

    swell::Renderer direct(scene);
    const swell::Image once = direct.renderImage(camera, kBodiesRenderTime_s, kBodiesRenderSize);

    // A viewer's frames: uneven steps, one of them back in time (a scrub).
    swell::Renderer viewer(scene);
    for (double t : {0.0, 0.4, 1.37, 2.0, 1.1, 3.33, 5.02, 6.49})
        (void)viewer.renderImage(swell::cameraAt(scene.camera, t), t, kBodiesRenderSize);
    const swell::Image afterFrames = viewer.renderImage(camera, kBodiesRenderTime_s, kBodiesRenderSize);

    const swell::ImageDifference d = swell::compareImages(once, afterFrames);
    EXPECT_EQ(d.maxChannel, 0) << swell::test::saveTestImage(once, "bodies_render_once") << " vs "
                               << swell::test::saveTestImage(afterFrames, "bodies_render_after_frames");

    // The bodies are in view and move by themselves: the scene whose
    // objects only sit on the surface draws them elsewhere.
    swell::Scene riders = scene;
    for (swell::SceneObject& o : riders.objects) {
        o.density_kg_per_m3 = 0.0;
        o.velocity_m_per_s = glm::dvec3(0.0);
    }
    swell::Renderer still(riders);
    const swell::Image ridden = still.renderImage(camera, kBodiesRenderTime_s, kBodiesRenderSize);
    int changed = 0;
    for (std::size_t i = 0; i < once.rgba.size(); i += 4)
        changed += std::abs(int(once.rgba[i]) - int(ridden.rgba[i])) > 8;
    EXPECT_GT(changed, 100) << "the rigid bodies look like riders: " << swell::test::saveTestImage(ridden, "bodies_render_riders");
}

// What the user gave is refused with a reason, and the renderer is not built.
TEST_F(BodiesRender, BadBodiesAndHullNodesAreRefused)
{
    const std::filesystem::path folder = std::filesystem::path(SWELL_TEST_OUTPUT_DIR) / "bodies_render";
    std::filesystem::create_directories(folder);
    swell::test::writeGltf({{"Boat", swell::detail::makeBuiltinModel("boat")},
                            {"Hull", swell::detail::makeBuiltinHullVolume("boat")}},
                           folder / "boat.gltf");
    swell::Scene scene = bodiesScene();
    scene.assetFolder = folder.string();
    scene.objects[0].path = "boat.gltf";
    scene.objects[0].hullNode = "Keel";
    try {
        swell::Renderer renderer(scene);
        FAIL() << "a missing hull node was accepted";
    } catch (const swell::InputError& e) {
        EXPECT_NE(e.message().find("no node named 'Keel'"), std::string::npos) << e.what();
        EXPECT_NE(e.message().find("'Hull'"), std::string::npos) << "the names it has: " << e.what();
    }
    // The open boat without its hull node is no closed body.
    scene.objects[0].hullNode.clear();
    EXPECT_THROW(swell::Renderer{scene}, swell::InputError);
    // Heavier than the water it can displace: it would sink.
    scene.objects[0].hullNode = "Hull";
    scene.objects[0].density_kg_per_m3 = 2000.0;
    try {
        swell::Renderer renderer(scene);
        FAIL() << "a sinking body was accepted";
    } catch (const swell::InputError& e) {
        EXPECT_NE(e.message().find("sinks"), std::string::npos) << e.what();
        EXPECT_NE(e.message().find("objects[0]"), std::string::npos) << e.what();
    }
}

} // namespace
