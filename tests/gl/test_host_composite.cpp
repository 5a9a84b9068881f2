// The water in a host's frame (swell/view.h, Renderer::draw): a host draws
// its own boxes with its own shader, then Swell draws the water into the
// host's framebuffer, depth-tested against the host's depth, with the host's
// boxes in its reflection through the pass callback. Held for a level
// camera, a camera rolled 30 degrees, reversed-Z with an infinite far plane,
// and the sea level at 100 m.
#include "host_frame.h"
#include "support/gl_test.h"

#include "swell/camera.h"
#include "swell/error.h"
#include "swell/flat_model.h"
#include "swell/image.h"
#include "swell/renderer.h"

#include <epoxy/gl.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <cstdint>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace {

using swell::test::GlTest;
using swell::test::HostBox;
using swell::test::HostScene;
using swell::test::HostTarget;

constexpr glm::ivec2 kHostCompositeSize{320, 180};
const glm::vec4 kHostClear{0.1f, 0.9f, 0.1f, 1.0f}; // a green no water or sky has
const glm::vec3 kCubeColor{1.0f, 0.0f, 0.0f};
const glm::vec3 kWallColor{0.6f, 0.6f, 0.65f};

struct Config {
    std::string name;
    double roll_deg = 0.0;
    bool reversedZ = false;
    double level_m = 0.0;
};

void PrintTo(const Config& c, std::ostream* os) { *os << c.name; }

// Calm water that mirrors perfectly (Fresnel F0 = 1, no glint, no fog), and
// nothing of Swell's own world.
swell::Scene mirrorScene(double level_m)
{
    swell::Scene scene = swell::defaultScene();
    scene.showTerrain = false;
    scene.objects.clear();
    scene.sea.level_m = level_m;
    scene.water.fresnelF0 = 1.0;
    scene.water.specularStrength = 0.0;
    scene.fog.start_m = 90000.0;
    scene.fog.end_m = 100000.0;
    return scene;
}

// A reversed-Z projection with its far plane at infinity: clip z = near, w = -z_eye.
glm::dmat4 reversedInfinite(double fovY_deg, double aspect, double near_m)
{
    const double f = 1.0 / std::tan(glm::radians(fovY_deg) * 0.5);
    glm::dmat4 p(0.0);
    p[0][0] = f / aspect;
    p[1][1] = f;
    p[2][3] = -1.0;
    p[3][2] = near_m;
    return p;
}

swell::View hostView(const Config& c)
{
    swell::Camera camera;
    camera.position_m = {0.0, c.level_m + 3.0, 0.0};
    camera.pitch_deg = -6.0;
    camera.roll_deg = c.roll_deg;
    swell::View view = swell::viewOf(camera, kHostCompositeSize);
    if (c.reversedZ) {
        view.projection = reversedInfinite(camera.fovY_deg, double(kHostCompositeSize.x) / kHostCompositeSize.y, camera.near_m);
        view.depth = swell::DepthMode::Reversed;
    }
    return view;
}

HostBox cube(double level_m) { return {{2.5, level_m + 1.0, -27.0}, {5.5, level_m + 4.0, -24.0}, kCubeColor}; }
HostBox wall(double level_m) { return {{-9.0, level_m + 0.5, -12.2}, {-3.0, level_m + 5.0, -12.0}, kWallColor}; }

struct Pixels {
    std::vector<std::uint8_t> rgba;
    glm::u8vec4 at(int x, int y) const
    {
        const std::size_t i = (std::size_t(y) * kHostCompositeSize.x + std::size_t(x)) * 4;
        return {rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]};
    }
};

// The frame as a PNG in the test output folder, for a person to look at.
void writeFrame(const Pixels& p, const std::string& name)
{
    swell::Image image;
    image.width = kHostCompositeSize.x;
    image.height = kHostCompositeSize.y;
    image.rgba.resize(p.rgba.size());
    const std::size_t row = std::size_t(kHostCompositeSize.x) * 4;
    for (int y = 0; y < kHostCompositeSize.y; ++y)
        std::copy_n(&p.rgba[std::size_t(kHostCompositeSize.y - 1 - y) * row], row, &image.rgba[std::size_t(y) * row]);
    std::filesystem::create_directories(SWELL_TEST_OUTPUT_DIR);
    swell::writePng(image, std::string(SWELL_TEST_OUTPUT_DIR) + "/" + name + ".png");
}

bool isRed(glm::u8vec4 p) { return p.r > 110 && p.g < 60 && p.b < 60; }

// A mask of the pixels where `boxes` alone cover the frame, seen through viewProj.
std::vector<bool> coverage(const std::vector<HostBox>& boxes, const swell::View& view, const glm::dmat4& world)
{
    HostTarget target(kHostCompositeSize, GL_RGBA8, view.depth == swell::DepthMode::Reversed ? GL_DEPTH_COMPONENT32F : GL_DEPTH_COMPONENT24);
    HostScene scene(boxes);
    swell::View v = view;
    v.view = view.view * world;
    swell::test::drawHostFrame(target, scene, v, glm::vec4(0.0f));
    const Pixels p{target.pixels()};
    std::vector<bool> mask(std::size_t(kHostCompositeSize.x) * kHostCompositeSize.y);
    for (int y = 0; y < kHostCompositeSize.y; ++y)
        for (int x = 0; x < kHostCompositeSize.x; ++x)
            mask[std::size_t(y) * kHostCompositeSize.x + std::size_t(x)] = p.at(x, y).a > 0;
    glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    return mask;
}

// Whether any pixel of `mask` lies within `radius` pixels of (x, y), or, for
// all = true, whether every pixel there does (pixels off the frame are skipped).
bool near(const std::vector<bool>& mask, int x, int y, int radius, bool all)
{
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
            const int u = x + dx, v = y + dy;
            if (u < 0 || v < 0 || u >= kHostCompositeSize.x || v >= kHostCompositeSize.y)
                continue;
            const bool in = mask[std::size_t(v) * kHostCompositeSize.x + std::size_t(u)];
            if (all && !in)
                return false;
            if (!all && in)
                return true;
        }
    return all;
}

class HostComposite : public GlTest, public ::testing::WithParamInterface<Config> {};

TEST_P(HostComposite, TheHostsCubeIsMirroredItsWallHidesTheWaterAndNothingElseChanges)
{
    const Config c = GetParam();
    const swell::Scene scene = mirrorScene(c.level_m);
    swell::Renderer renderer(scene);
    renderer.setWaveModel(std::make_shared<swell::FlatModel>());
    const swell::View view = hostView(c);
    const std::vector<HostBox> boxes{cube(c.level_m), wall(c.level_m)};
    HostScene host(boxes);
    HostTarget target(kHostCompositeSize, GL_RGBA8, c.reversedZ ? GL_DEPTH_COMPONENT32F : GL_DEPTH_COMPONENT24);
    swell::test::drawHostFrame(target, host, view, kHostClear);
    const Pixels before{target.pixels()};

    renderer.advanceTo(10.0, view.eye_m());
    swell::DrawOptions options;
    options.geometry = &host;
    options.sky = false;
    renderer.draw(view, target.framebuffer(), options);
    const Pixels after{target.pixels()};
    writeFrame(after, "host_composite_" + c.name);
    ASSERT_EQ(host.passes.size(), 2u);
    EXPECT_EQ(host.passes[0], swell::PassKind::Reflection);
    EXPECT_EQ(host.passes[1], swell::PassKind::Refraction);

    // Where the host's boxes are, and where their mirror image about the sea level would be.
    const std::vector<bool> boxesMask = coverage(boxes, view, glm::dmat4(1.0));
    const glm::dmat4 mirror = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, c.level_m, 0.0)) *
                              glm::scale(glm::dmat4(1.0), glm::dvec3(1.0, -1.0, 1.0)) *
                              glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, -c.level_m, 0.0));
    const std::vector<bool> cubeMirror = coverage({cube(c.level_m)}, view, mirror);
    const glm::dmat4 inverse = glm::inverse(view.projection * view.view);

    int water = 0, reflected = 0, footprintOnWater = 0, strayRed = 0, unfilled = 0, changedHost = 0, changedSky = 0;
    for (int y = 0; y < kHostCompositeSize.y; ++y)
        for (int x = 0; x < kHostCompositeSize.x; ++x) {
            const std::size_t i = std::size_t(y) * kHostCompositeSize.x + std::size_t(x);
            const bool changed = after.at(x, y) != before.at(x, y);
            // The pixel's ray: does it head up, well above the horizon?
            const glm::dvec2 ndc((x + 0.5) / kHostCompositeSize.x * 2.0 - 1.0, (y + 0.5) / kHostCompositeSize.y * 2.0 - 1.0);
            const double nearZ = c.reversedZ ? 1.0 : -1.0;
            const glm::dvec4 p = inverse * glm::dvec4(ndc, nearZ, 1.0);
            const glm::dvec3 direction = glm::normalize(glm::dvec3(p) / p.w - view.eye_m());
            if (boxesMask[i]) {
                changedHost += changed;
                continue;
            }
            if (direction.y > 0.02) {
                changedSky += changed;
                continue;
            }
            if (!changed || direction.y > -0.02)
                continue;
            ++water;
            const bool red = isRed(after.at(x, y));
            reflected += red;
            if (red && !near(cubeMirror, x, y, 2, false))
                ++strayRed;
            if (near(cubeMirror, x, y, 2, true)) {
                ++footprintOnWater;
                unfilled += !red;
            }
        }
    EXPECT_GT(water, kHostCompositeSize.x * kHostCompositeSize.y / 4) << "the water was drawn";
    EXPECT_EQ(changedHost, 0) << "the host's boxes hide the water behind them, and are not drawn over";
    EXPECT_EQ(changedSky, 0) << "nothing changes above the horizon (no sky asked for)";
    EXPECT_GT(footprintOnWater, 100) << "the cube's mirror image lies on the water";
    EXPECT_EQ(strayRed, 0) << "the cube's reflection lies inside its mirror footprint within 2 px";
    EXPECT_EQ(unfilled, 0) << "and fills it (" << reflected << " red water pixels)";
}

// From under the water, the host's geometry below the surface is seen
// through the water: absorbed (red first) and filled in by its scattered
// light, as Swell's own objects are; with a linear target, exactly
// host colour * transmittance + in-scattering.
TEST_P(HostComposite, TheHostsGeometryUnderTheWaterIsSeenThroughIt)
{
    const Config c = GetParam();
    const swell::Scene scene = mirrorScene(c.level_m);
    swell::Renderer renderer(scene);
    renderer.setWaveModel(std::make_shared<swell::FlatModel>());
    swell::Camera camera;
    camera.position_m = {0.0, c.level_m - 3.0, 0.0};
    camera.pitch_deg = -10.0;
    camera.roll_deg = c.roll_deg;
    swell::View view = swell::viewOf(camera, kHostCompositeSize);
    if (c.reversedZ) {
        view.projection = reversedInfinite(camera.fovY_deg, double(kHostCompositeSize.x) / kHostCompositeSize.y, camera.near_m);
        view.depth = swell::DepthMode::Reversed;
    }
    // A white block 12 m ahead, from 8 m down to 4 m down.
    const HostBox block{{-3.0, c.level_m - 8.0, -14.0}, {3.0, c.level_m - 4.0, -10.0}, {1.0f, 1.0f, 1.0f}};
    HostScene host({block});
    HostTarget target(kHostCompositeSize, GL_RGBA16F, c.reversedZ ? GL_DEPTH_COMPONENT32F : GL_DEPTH_COMPONENT24);
    swell::test::drawHostFrame(target, host, view, kHostClear);
    renderer.advanceTo(10.0, view.eye_m());
    swell::DrawOptions options;
    options.geometry = &host;
    options.sky = false;
    options.encoding = swell::OutputEncoding::Linear;
    renderer.draw(view, target.framebuffer(), options);
    const std::vector<float> after = target.floatPixels();
    Pixels shown; // display-encoded, for a person to look at
    for (float value : after) {
        const float v = std::clamp(value, 0.0f, 1.0f);
        const float encoded = v < 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
        shown.rgba.push_back(std::uint8_t(std::lround(encoded * 255.0f)));
    }
    for (std::size_t i = 3; i < shown.rgba.size(); i += 4)
        shown.rgba[i] = 255;
    writeFrame(shown, "host_underwater_" + c.name);
    const std::vector<bool> blockMask = coverage({block}, view, glm::dmat4(1.0));
    int pixels = 0, redAbsorbedMost = 0;
    glm::dvec3 sum(0.0);
    for (std::size_t i = 0; i < blockMask.size(); ++i) {
        if (!blockMask[i])
            continue;
        const glm::dvec3 rgb(after[4 * i], after[4 * i + 1], after[4 * i + 2]);
        ++pixels;
        sum += rgb;
        redAbsorbedMost += rgb.r < rgb.g && rgb.r < rgb.b && rgb.r < 0.2;
    }
    ASSERT_GT(pixels, 500);
    EXPECT_EQ(redAbsorbedMost, pixels) << "the white block is seen through metres of water: red is absorbed first";
    // Its centre, 12 m from the eye along a path of about 12.4 m, 4 to 8 m
    // down: white * exp(-a (depth + path)) + in-scattering, per channel.
    const glm::dvec3 mean = sum / double(pixels);
    const glm::dvec3 a = scene.water.absorption_per_m;
    EXPECT_LT(mean.r, 0.05);
    EXPECT_GT(mean.g, std::exp(-a.y * (8.0 + 14.5))) << "green is absorbed less than the path's longest allows";
    EXPECT_LT(mean.g, std::exp(-a.y * (4.0 + 10.0)) + 0.1) << "and at least as much as its shortest";
}

std::string configName(const ::testing::TestParamInfo<Config>& info) { return info.param.name; }

INSTANTIATE_TEST_SUITE_P(Views, HostComposite,
                         ::testing::Values(Config{"Level"}, Config{"Rolled30", 30.0}, Config{"ReversedZ", 0.0, true},
                                           Config{"SeaLevel100m", 0.0, false, 100.0},
                                           Config{"RolledReversedAt100m", 30.0, true, 100.0}),
                         configName);

} // namespace
