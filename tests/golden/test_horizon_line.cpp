// No line of the depths' colour along the horizon, seen from the air, at any
// far plane and camera height, and in every preset (issue 28, item 2).
//
// A pixel whose view ray meets no drawn water is judged under or above the
// water from where that ray leaves the water the renderer draws
// (shaders/underwater.glsl). Judged from where it meets the far plane
// instead, a ray from the air that passes beyond the water grid's skirt
// before it sinks below the mean level was taken as under water and drawn in
// the depths' colour: a one-pixel line at the horizon, at the image's borders
// (where the far plane reaches past the square skirt) or across the width.
//
// The water's deep colour is set to a marker no sky, fog or water seen from
// the air can take: magenta with no green. Seen from the air, water always
// reflects some sky (at least F0 = 2% of it, with green in every preset's
// sky and fog), so only a pixel judged under water shows the marker's pure
// colour (the background below the surface is the deep colour unlit by
// anything else).
#include "support/gl_test.h"
#include "support/golden.h"
#include "swell/camera.h"
#include "swell/renderer.h"
#include "swell/scene/parameters.h"
#include "swell/scene/scene_file.h"

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace {

class HorizonLine : public swell::test::GlTest {};

const glm::dvec3 kMarker{1.0, 0.0, 1.0};

// A pixel in the marker's colour: the depths' background (sRGB-encoded,
// so 255, 0, 255) and nothing a view from the air mixes with reflected sky.
bool isMarker(const std::uint8_t* p) { return p[1] <= 8 && p[0] >= 128 && p[2] >= 128; }

// The image row where the mean level's horizon (direction.y = 0) lies, for
// a camera pitched pitch_deg (negative: down) with a vertical field fovY_deg.
double horizonRow(double pitch_deg, double fovY_deg, int height)
{
    const double half = 0.5 * height;
    return half - std::tan(glm::radians(-pitch_deg)) / std::tan(glm::radians(0.5 * fovY_deg)) * half;
}

struct Found {
    int count = 0;
    int firstX = -1, firstY = -1;
};

// Marker pixels in rows y0..y1 (clamped to the image), every column.
Found scanRows(const swell::Image& image, int y0, int y1)
{
    Found f;
    for (int y = std::max(y0, 0); y <= std::min(y1, image.height - 1); ++y)
        for (int x = 0; x < image.width; ++x)
            if (isMarker(image.pixel(x, y))) {
                if (f.count++ == 0) {
                    f.firstX = x;
                    f.firstY = y;
                }
            }
    return f;
}

// The storm preset (waves that reach the near plane of a camera some metres
// up, so the waterline mask is drawn pixel by pixel), at far planes from the
// table's smallest to its largest and cameras from 2 to 300 m, looking
// along an axis of the grid's square skirt and 40 degrees off it. Every
// row from above the horizon down to where a ray reaches the mean level 50 m
// out is scanned across the whole width, the borders included. The waves
// are not choppy here: a choppy crest can fold over, and the mask rightly
// says that a fold's underside is seen from below (a speck of the depths'
// colour, which is not the line this test is about).
TEST_F(HorizonLine, NoDepthsColourAtAnyFarPlaneOrCameraHeight)
{
    swell::Scene scene = swell::loadScene(std::string(SWELL_SOURCE_DIR) + "/scenes/storm.toml");
    scene.antialiasing = swell::Antialiasing::Off;
    scene.water.deepColor = kMarker;
    scene.waves.choppiness = 0.0;
    const swell::Parameter* far = swell::findParameter("camera.far_m");
    ASSERT_NE(far, nullptr);
    // The smallest far plane the checks accept is just beyond the near one.
    const double farMin_m = std::max(far->min, scene.camera.near_m) * 1.001 + 1e-3;
    const std::vector<double> farPlanes_m{farMin_m, 10.0, 100.0, 1000.0, 5000.0, 20000.0, 1.0e5, 1.0e6, far->max};
    const std::vector<double> heights_m{2.0, 7.0, 10.0, 37.0, 100.0, 300.0};
    const std::vector<double> yaws_deg{0.0, 40.0};
    const glm::ivec2 size{480, 270};
    const double time_s = 20.0;
    swell::Renderer renderer(scene);
    int views = 0, failed = 0;
    for (double far_m : farPlanes_m) {
        scene.camera.far_m = far_m;
        renderer.setScene(scene);
        for (double height_m : heights_m)
            for (double yaw_deg : yaws_deg) {
                swell::Camera camera = swell::cameraAt(scene.camera, time_s);
                camera.position_m.y = height_m;
                camera.yaw_deg = yaw_deg;
                const swell::Image image = renderer.renderImage(camera, time_s, size);
                const double horizon = horizonRow(camera.pitch_deg, camera.fovY_deg, size.y);
                // 50 m out, the mean level lies atan(h / 50) below the horizon.
                const double below = horizonRow(camera.pitch_deg + glm::degrees(std::atan(height_m / 50.0)),
                                                camera.fovY_deg, size.y);
                const Found f = scanRows(image, int(std::floor(horizon)) - 4, int(std::ceil(below)));
                ++views;
                if (f.count > 0) {
                    ++failed;
                    ADD_FAILURE() << f.count << " pixels of the depths' colour near the horizon (row "
                                  << horizon << "), first at " << f.firstX << "," << f.firstY << ": far_m " << far_m
                                  << ", camera " << height_m << " m up, yaw " << yaw_deg << " deg: "
                                  << swell::test::saveTestImage(image, "horizon_line_far" + std::to_string(int(far_m)) +
                                                                           "_h" + std::to_string(int(height_m)) + "_yaw" +
                                                                           std::to_string(int(yaw_deg)));
                }
            }
    }
    EXPECT_EQ(views, int(farPlanes_m.size() * heights_m.size() * yaws_deg.size()));
    EXPECT_EQ(failed, 0);
}

// The swell's crests on the horizon through a long lens (the storm 7 m up,
// a 10 degree lens 0.49 degrees down, where its far crests' ridges lie 700
// to 1200 m off): no pixel of the depths' colour along their ridges. There
// the front and back faces of a crest meet closer than a standard depth
// buffer tells apart at that distance, so the waterline mask compares the
// distance to the eye instead (waterline.frag): with the frame's depth,
// pixels of this view were seen from below (945,257).
TEST_F(HorizonLine, NoDepthsColourAlongTheCrestsOfTheHorizonsSwell)
{
    swell::Scene scene = swell::loadScene(std::string(SWELL_SOURCE_DIR) + "/scenes/storm.toml");
    scene.antialiasing = swell::Antialiasing::Off;
    scene.water.deepColor = kMarker;
    scene.waves.choppiness = 0.0; // no folds, whose undersides are seen from below
    scene.camera.position_m = {0.0, 7.0, 0.0};
    scene.camera.yaw_deg = -36.6;
    scene.camera.pitch_deg = -0.49;
    scene.camera.fovY_deg = 10.0;
    swell::Renderer renderer(scene);
    const double time_s = 20.0;
    const swell::Image image = renderer.renderImage(swell::cameraAt(scene.camera, time_s), time_s, {960, 540});
    const Found f = scanRows(image, 0, image.height - 1);
    EXPECT_EQ(f.count, 0) << "first at " << f.firstX << "," << f.firstY << ": "
                          << swell::test::saveTestImage(image, "horizon_line_long_lens");
}

// Every preset in scenes/ whose camera is in the air, at the README's
// pictures' size and time: the horizon's row and the rows next to it, at
// both borders (where the far plane reaches furthest past the water's
// square skirt), show no pixel of the depths' colour.
TEST_F(HorizonLine, NoPresetShowsTheDepthsColourAtTheHorizonsBorders)
{
    const glm::ivec2 size{960, 540};
    const double time_s = 20.0;
    const int border = 48; // a twentieth of the width, each side
    int presets = 0;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(SWELL_SOURCE_DIR) + "/scenes")) {
        if (entry.path().extension() != ".toml")
            continue;
        swell::Scene scene = swell::loadScene(entry.path());
        const swell::Camera camera = swell::cameraAt(scene.camera, time_s);
        if (camera.position_m.y <= 0.0)
            continue; // a view from below the surface has the depths' colour by right
        ++presets;
        scene.antialiasing = swell::Antialiasing::Off;
        scene.water.deepColor = kMarker;
        swell::Renderer renderer(scene);
        const swell::Image image = renderer.renderImage(camera, time_s, size);
        const int horizon = int(std::lround(horizonRow(camera.pitch_deg, camera.fovY_deg, size.y)));
        int count = 0;
        for (int y = std::max(horizon - 2, 0); y <= std::min(horizon + 2, size.y - 1); ++y)
            for (int x = 0; x < size.x; ++x)
                if ((x < border || x >= size.x - border) && isMarker(image.pixel(x, y)))
                    ++count;
        EXPECT_EQ(count, 0) << entry.path().filename().string() << ": pixels of the depths' colour at the borders of row "
                            << horizon << ": " << swell::test::saveTestImage(image, "horizon_line_" + entry.path().stem().string());
    }
    EXPECT_GE(presets, 7); // every preset but the one under the water
}

} // namespace
