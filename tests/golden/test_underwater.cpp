// The view from under the water: Snell's window measured in the image
// against the critical angle, the water's absorption against Beer-Lambert
// with the scene's coefficients, and the waterline split of a camera in the
// waves against the CPU's surface at the near plane. Each then a golden.
#include "support/gl_test.h"
#include "support/golden.h"
#include "support/stage.h"
#include "swell/flat_model.h"
#include "swell/renderer.h"
#include "swell/scene/grid.h"
#include "swell/scene/scene_file.h"
#include "swell/wave_model.h"

#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

namespace {

using swell::test::srgbLevel;
using swell::test::srgbToLinear;

class Underwater : public swell::test::GlTest {};

double underwaterLuminance(const std::uint8_t* p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; }

// The inverse of the camera's view-projection, for positions relative to
// the render origin (the camera's x,z at y = 0), as the renderer draws.
struct PixelRays {
    swell::Camera camera;
    glm::ivec2 size;
    glm::dmat4 inverse;
    glm::dvec3 origin;

    PixelRays(const swell::Camera& c, glm::ivec2 s) : camera(c), size(s), origin(c.position_m.x, 0.0, c.position_m.z)
    {
        inverse = glm::inverse(c.projection(double(s.x) / s.y) * c.viewRelativeTo(origin));
    }
    // The world point of pixel (x, y) (from the top left) at NDC depth z (-1: near plane, 1: far).
    glm::dvec3 at(int x, int y, double z) const
    {
        const glm::dvec4 ndc((x + 0.5) / size.x * 2.0 - 1.0, 1.0 - (y + 0.5) / size.y * 2.0, z, 1.0);
        const glm::dvec4 p = inverse * ndc;
        return glm::dvec3(p) / p.w + origin;
    }
    glm::dvec3 direction(int x, int y) const { return glm::normalize(at(x, y, 1.0) - at(x, y, -1.0)); }
};

// Snell's window's half-angle for sea water (n = 1.333 into air, n = 1):
// asin(1 / 1.333) = 48.6 degrees, the figure the issue gives.
constexpr double kCriticalAngle_deg = 48.6;

TEST_F(Underwater, SnellsWindowHasTheCriticalAngleAndWaterColourOutside)
{
    swell::Scene scene = swell::test::emptyStage();
    // The window alone: the water's glow about the sun's refracted direction
    // (water.shafts) reaches past the window's edge, and would be taken
    // for the sky there (tests/golden/test_light_shafts_render.cpp).
    scene.water.shafts = false;
    swell::Renderer renderer(scene);
    renderer.setWaveModel(std::make_shared<swell::FlatModel>()); // calm water
    swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    camera.position_m = {0.0, -5.0, 0.0};
    camera.pitch_deg = 89.0; // the camera's limit; each pixel's angle is computed, not assumed
    camera.fovY_deg = 120.0; // the window's edge and 20 degrees beyond it fit in a square image
    const glm::ivec2 size{240, 240};
    const swell::Image image = renderer.renderImage(camera, 0.0, size);
    const PixelRays rays(camera, size);

    // Each pixel's angle from the vertical, with its luminance, binned by 0.25 degree.
    constexpr double kBin_deg = 0.25;
    std::vector<double> sum(400, 0.0), count(400, 0.0);
    std::vector<double> inside, outside;
    std::vector<std::array<int, 2>> outsidePixels;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            const double angle_deg = glm::degrees(std::acos(std::clamp(rays.direction(x, y).y, -1.0, 1.0)));
            const double lum = underwaterLuminance(image.pixel(x, y));
            const auto bin = size_t(angle_deg / kBin_deg);
            if (bin < sum.size()) {
                sum[bin] += lum;
                count[bin] += 1.0;
            }
            if (angle_deg < 40.0)
                inside.push_back(lum);
            else if (angle_deg > 50.0) {
                outside.push_back(lum);
                outsidePixels.push_back({x, y});
            }
        }
    ASSERT_GT(outside.size(), 1000u) << "the view does not reach past the window";
    auto median = [](std::vector<double> v) {
        std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
        return v[v.size() / 2];
    };
    const double skyLevel = median(inside), waterLevel = median(outside);
    ASSERT_GT(skyLevel, waterLevel + 60.0) << "no bright window: " << swell::test::saveTestImage(image, "snell.actual");
    // The window's edge: the first bin beyond 40 degrees whose mean luminance
    // falls below halfway between the sky inside and the water outside.
    // Fresnel's reflectance rises from 26% at 47 degrees to 100% at 48.6, so
    // halfway sits a few tenths of a degree inside the critical angle.
    const double halfway = 0.5 * (skyLevel + waterLevel);
    double edge_deg = -1.0;
    for (size_t b = size_t(40.0 / kBin_deg); b < sum.size(); ++b)
        if (count[b] > 0.0 && sum[b] / count[b] < halfway) {
            edge_deg = (double(b) + 0.5) * kBin_deg;
            break;
        }
    std::printf("Snell's window: edge at %.2f deg (sky %.0f, water %.0f luminance)\n", edge_deg, skyLevel, waterLevel);
    // +-1 degree: the tolerance; a bin is 0.25 degree and a pixel here 0.2 to 0.5.
    EXPECT_NEAR(edge_deg, kCriticalAngle_deg, 1.0) << "sky " << skyLevel << ", water " << waterLevel << ": "
                                                   << swell::test::saveTestImage(image, "snell.actual");
    // Beyond the window the surface reflects the water: no pixel there may be
    // as bright as halfway to the sky, nor have the sky's colour (the mean
    // colour just inside the edge, 44..46 degrees, where the window shows the
    // sky near the horizon).
    glm::dvec3 skyEdge(0.0);
    int skyEdgeCount = 0;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            const double angle_deg = glm::degrees(std::acos(rays.direction(x, y).y));
            if (angle_deg > 44.0 && angle_deg < 46.0) {
                const std::uint8_t* p = image.pixel(x, y);
                skyEdge += glm::dvec3(p[0], p[1], p[2]);
                ++skyEdgeCount;
            }
        }
    skyEdge /= double(std::max(skyEdgeCount, 1));
    int skyColoured = 0;
    for (const auto& xy : outsidePixels) {
        const std::uint8_t* p = image.pixel(xy[0], xy[1]);
        // 40 levels: far more than rounding; the water outside differs from the sky by over a hundred.
        const bool nearSky = glm::length(glm::dvec3(p[0], p[1], p[2]) - skyEdge) < 40.0;
        if (underwaterLuminance(p) >= halfway || nearSky)
            ++skyColoured;
    }
    EXPECT_EQ(skyColoured, 0) << "pixels beyond 50 degrees look like sky (sky edge colour " << skyEdge.x << ","
                              << skyEdge.y << "," << skyEdge.z << ")";
    // 48 / 0.6, as for the other goldens: another CPU's rounding moves a few
    // pixels at the window's edge by a few levels; a window of another size
    // (n = 1.2 gives 56 degrees) moves a ring of hundreds of pixels by tens of levels.
    swell::test::expectMatchesGolden(image, "underwater_snells_window", 48, 0.6);
}

TEST_F(Underwater, WaterAbsorbsEachChannelAsBeerLambertSays)
{
    // A rock (a lumpy dome 6 m across) standing in the water, seen level
    // from 2 m deep, from two distances along one line: the centre pixel
    // sees the same point of it, lit alike, through 2 m more water the
    // second time. Beer-Lambert (the scene's model, refraction.glsl):
    // seen = rock * exp(-a s) + background * (1 - exp(-a s)), so the rock's
    // contrast against the background shrinks by exp(-a * 2 m) per channel.
    swell::Scene scene = swell::test::emptyStage();
    scene.water.absorption_per_m = {0.45, 0.09, 0.06};
    scene.sun.direction = {0.0, 0.6, 0.8}; // behind the camera, lighting the rock's face
    auto render = [&](bool withRock, double cameraZ_m) {
        swell::Scene s = scene;
        if (withRock)
            s.objects.push_back({"builtin:rock", {0.0, -3.0, -10.0}, 0.0, 1.0, false});
        swell::Renderer renderer(s);
        renderer.setWaveModel(std::make_shared<swell::FlatModel>());
        swell::Camera camera = swell::cameraAt(s.camera, 0.0);
        camera.position_m = {0.0, -2.0, cameraZ_m};
        camera.yaw_deg = 0.0;
        camera.pitch_deg = 0.0;
        return renderer.renderImage(camera, 0.0, {160, 120});
    };
    const swell::Image nearRock = render(true, -5.5);
    const swell::Image farRock = render(true, -3.5);
    const swell::Image water = render(false, -5.5);
    const std::uint8_t* n = nearRock.pixel(80, 60);
    const std::uint8_t* f = farRock.pixel(80, 60);
    const std::uint8_t* w = water.pixel(80, 60);
    for (int c = 0; c < 3; ++c) {
        const double nearContrast = srgbToLinear(n[c]) - srgbToLinear(w[c]);
        const double farContrast = srgbToLinear(f[c]) - srgbToLinear(w[c]);
        ASSERT_GT(nearContrast, 0.01) << "channel " << c << ": the rock does not stand out at all: "
                                      << swell::test::saveTestImage(nearRock, "absorption_near.actual");
        const double expected = std::exp(-scene.water.absorption_per_m[c] * 2.0);
        std::printf("channel %d: contrast through 2 m more water x%.3f, Beer-Lambert x%.3f\n", c,
                    farContrast / nearContrast, expected);
        // 0.04: 8-bit rounding of the far red contrast (about 0.03 linear)
        // is up to 3% of it; red 0.41, green 0.84, blue 0.89 are far apart.
        EXPECT_NEAR(farContrast / nearContrast, expected, 0.04) << "channel " << c;
    }
    // 48 / 0.6: as for the other goldens; no absorption (or one coefficient
    // for all channels) recolours the whole rock by tens of levels.
    swell::test::expectMatchesGolden(nearRock, "underwater_absorption", 48, 0.6);
}

TEST_F(Underwater, CameraInTheWavesSplitsTheViewAtTheWaterline)
{
    // The default sea without island or objects; the eye 10 cm under the
    // surface at its feet, looking level. Where the near plane's point of a
    // pixel lies under the surface (the CPU's height there), the pixel must
    // show the dark water; where it lies above, the bright sky and sea.
    swell::Scene scene = swell::defaultScene();
    scene.showTerrain = false;
    scene.objects.clear();
    scene.fog.start_m = 1.0e5;
    scene.fog.end_m = 2.0e5;
    // Cells of 8 cm by the eye: the drawn split then follows the surface
    // the CPU computes to a pixel row (with the default 0.33 m cells, the flat
    // triangles sit up to 15 mm, 3 rows, off the curved surface between vertices).
    scene.grid.resolution = 481;
    // Water that scatters no blue: under the surface no blue reaches the eye
    // (the view stays outside Snell's window, which begins 41 degrees up),
    // while from the air the sea reflects at least 2% of the blue sky.
    scene.water.deepColor = {0.02, 0.08, 0.0};
    // Nor the sun's light: the shafts of light (water.shafts) scatter its
    // blue towards the eye (tests/golden/test_light_shafts_render.cpp).
    scene.water.shafts = false;
    swell::Renderer renderer(scene);
    const double time_s = 3.0;
    swell::Camera camera = swell::cameraAt(scene.camera, time_s);
    camera.position_m = {0.0, 0.0, 0.0};
    camera.position_m.y = renderer.waveModel().heightAt({0.0, 0.0}, time_s) - 0.1;
    camera.pitch_deg = 0.0;
    // A near plane 1 m out, 1.15 m tall, spanning a wave's slope: a pixel
    // row is 5 mm of height on it (0.5 mm with the usual 0.1 m near plane,
    // finer than any grid follows the surface).
    camera.near_m = 1.0;
    const glm::ivec2 size{320, 240};
    const swell::Image image = renderer.renderImage(camera, time_s, size);
    const PixelRays rays(camera, size);
    // The surface as the grid draws it by the eye: without the waves its
    // cells there are too coarse to carry (they fade out below 4 cells per
    // wavelength), so the CPU is asked with the innermost cell as footprint.
    const swell::GridShape shape = swell::gridShapeFor(scene.grid, scene.camera);
    const swell::GridPlacement placement = swell::placeGrid(shape, camera.position_m);
    const swell::SurfaceFilter drawn{swell::gridPoint(shape, placement, shape.cells / 2, shape.cells / 2).cellSize_m, 1.0};
    int wrong = 0, checked = 0, above = 0, below = 0;
    for (int x = 0; x < size.x; x += 4) {
        for (int y = 0; y < size.y; ++y) {
            const auto underAt = [&](int row) {
                const glm::dvec3 p = rays.at(x, row, -1.0);
                return p.y < renderer.waveModel().heightAt({p.x, p.z}, time_s, drawn);
            };
            const bool under = underAt(y);
            // 2 px either side of the predicted line are left out: the mask
            // is rasterised from the grid's triangles, not the exact surface.
            if ((y >= 2 && underAt(y - 2) != under) || (y + 2 < size.y && underAt(y + 2) != under))
                continue;
            // Blue 12 (of 255): under the surface only the water's own colour,
            // blue 0 here; from the air the sky, or the sea reflecting it,
            // blue 84 and more here.
            const bool seenFromWater = image.pixel(x, y)[2] < 12;
            ++checked;
            (under ? below : above) += 1;
            if (seenFromWater != under)
                ++wrong;
        }
    }
    ASSERT_GT(above, 1000) << "the view shows no air: the test's camera is wrong";
    ASSERT_GT(below, 1000) << "the view shows no water: the test's camera is wrong";
    // No tolerance: a pixel on the wrong side away from the line is a flaw a viewer sees.
    EXPECT_EQ(wrong, 0) << "of " << checked << " pixels: " << swell::test::saveTestImage(image, "waterline.actual");
    // 48 / 0.6: as for the other goldens; the split moved by one pixel row
    // along the width is a few hundred pixels by a hundred levels, over the mean.
    swell::test::expectMatchesGolden(image, "underwater_waterline", 48, 0.6);
}

} // namespace

namespace {

// A camera in the air among storm waves (so the waterline mask is drawn)
// sees no dark line along the horizon: a ray just below the horizon meets
// the water only beyond the far plane, and is in the air all the way. When
// the mask's rays that meet no water were taken as under water whenever
// they pointed down, the horizon's row showed the depths' colour.
TEST_F(Underwater, AboveTheWavesTheHorizonHasNoUnderwaterLine)
{
    // The storm preset: waves high enough to reach the camera's near plane
    // from 10 m up, and a far plane (5 km) nearer than the water seen just
    // below the horizon.
    swell::Scene scene = swell::loadScene(std::string(SWELL_SOURCE_DIR) + "/scenes/storm.toml");
    scene.antialiasing = swell::Antialiasing::Off;
    const glm::ivec2 size{480, 270};
    swell::Renderer renderer(scene);
    const swell::Camera camera = swell::cameraAt(scene.camera, 20.0);
    const swell::Image image = renderer.renderImage(camera, 20.0, size);
    // The horizon's row: the camera looks pitch_deg below it.
    const double half = 0.5 * size.y;
    const int horizon = int(std::lround(
        half - std::tan(glm::radians(-camera.pitch_deg)) / std::tan(glm::radians(0.5 * scene.camera.fovY_deg)) * half));
    auto luma = [&](int x, int y) {
        const std::uint8_t* p = image.pixel(x, y);
        return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
    };
    // Sky above and fogged far water below are within a few levels of each
    // other there; the line was a third as bright as either.
    int dark = 0;
    for (int y = horizon - 4; y <= horizon + 4; ++y)
        for (int x = 0; x < size.x; ++x)
            if (luma(x, y) < 0.6 * std::min(luma(x, y - 5), luma(x, y + 5)))
                ++dark;
    EXPECT_LT(dark, size.x / 20) << swell::test::saveTestImage(image, "underwater_horizon_line");
}

} // namespace
