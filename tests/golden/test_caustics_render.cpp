// Caustics in the rendered frame (issue 25): a level floor under the water,
// seen straight down from under the surface, shows the waves' net of light
// (mesh.frag reads the caustics map), and under flat water none; the net
// moves light about, so the floor's mean stays that of flat water.
// tests/gl/test_caustics.cpp holds the map itself to the 5%.
#include "support/gl_test.h"
#include "support/golden.h"
#include "support/gltf_writer.h"
#include "support/stage.h"
#include "swell/camera.h"
#include "swell/flat_model.h"
#include "swell/renderer.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace {

class CausticsRender : public swell::test::GlTest {};

struct FloorStats {
    double mean = 0.0;     // of the pixels' linear luminance
    double contrast = 0.0; // their standard deviation over the mean
};

FloorStats floorStats(const swell::Image& image)
{
    double sum = 0.0, squares = 0.0;
    int count = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = image.pixel(x, y);
            const double l = 0.2126 * swell::test::srgbToLinear(p[0]) + 0.7152 * swell::test::srgbToLinear(p[1]) +
                             0.0722 * swell::test::srgbToLinear(p[2]);
            sum += l;
            squares += l * l;
            ++count;
        }
    FloorStats s;
    s.mean = sum / count;
    s.contrast = std::sqrt(std::max(squares / count - s.mean * s.mean, 0.0)) / s.mean;
    return s;
}

TEST_F(CausticsRender, AFloorUnderWavesShowsTheNetWithTheMeanOfFlatWater)
{
    const std::filesystem::path folder = std::filesystem::path(SWELL_TEST_OUTPUT_DIR) / "caustics_render";
    std::filesystem::create_directories(folder);
    // A pale box 40 m across whose top, the floor, lies 5 m down.
    swell::test::writeGltf(swell::test::makeBox(20.0f, glm::vec3(0.7f, 0.65f, 0.5f)), folder / "floor.gltf");
    swell::Scene scene = swell::test::emptyStage();
    scene.assetFolder = folder.string();
    scene.objects.push_back({"floor.gltf", {0.0, -25.0, 0.0}, 0.0, 1.0, false});
    scene.sun.direction = {0.2, 0.9, 0.3};
    scene.water.absorption_per_m = {0.40, 0.07, 0.09};
    // Ripples 1.5 to 4 m long (slopes a k about 0.16): a net of foci between 3 and 8 m down.
    scene.waves.listed = {{{1.0, 0.2}, 4.0, 0.10, 0.3, 0.0},
                                {{0.3, 1.0}, 2.5, 0.06, 0.3, 1.0},
                                {{-0.7, 0.6}, 1.5, 0.04, 0.3, 2.0}};
    // 1 m down looking straight down, 100 degrees across: 10 m of floor, a
    // few cells of the net each way.
    swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    camera.position_m = {0.0, -1.0, 0.0};
    camera.pitch_deg = -89.0;
    camera.fovY_deg = 100.0;
    const glm::ivec2 size(160, 160);
    swell::Renderer waves(scene);
    const swell::Image rippled = waves.renderImage(camera, 20.0, size);
    swell::Renderer level(scene);
    level.setWaveModel(std::make_shared<swell::FlatModel>());
    const swell::Image flat = level.renderImage(camera, 20.0, size);
    const FloorStats r = floorStats(rippled), f = floorStats(flat);
    std::printf("floor 5 m down: flat water mean %.4f contrast %.3f; ripples mean %.4f contrast %.3f\n", f.mean,
                f.contrast, r.mean, r.contrast);
    // Flat water lights the floor evenly: the view's own fall-off from
    // centre to edge (the path through the water to the edges is 1.6 times
    // that straight down) is all there is, measured 0.053.
    EXPECT_LT(f.contrast, 0.1) << swell::test::saveTestImage(flat, "caustics_flat.actual");
    // The waves' net: bright strands and dim cells (measured 0.60).
    EXPECT_GT(r.contrast, 3.0 * f.contrast) << swell::test::saveTestImage(rippled, "caustics_rippled.actual");
    EXPECT_GT(r.contrast, 0.1);
    // The same light on average (measured 3% apart). 10%, not the map's 5%: 10 m of floor holds
    // only a few cells of the net, and the sky's light and the path through
    // the water, which the net does not touch, are in both.
    EXPECT_NEAR(r.mean, f.mean, 0.10 * f.mean);
}

} // namespace
