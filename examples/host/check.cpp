#include "check.h"

#include "boxes.h"
#include "frame.h"
#include "gl_functions.h"

#include <swell/camera.h>
#include <swell/flat_model.h>
#include <swell/renderer.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace host {

namespace {

constexpr glm::ivec2 kSize{320, 180};
const float kHostClear[4] = {0.1f, 0.9f, 0.1f, 1.0f}; // a green no water has
const glm::vec3 kCubeColor{1.0f, 0.0f, 0.0f};
const glm::vec3 kWallColor{0.6f, 0.6f, 0.65f};

struct Config {
    const char* name;
    double roll_deg;
    bool reversedZ;
    double level_m;
};

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

swell::View checkView(const Config& c)
{
    swell::Camera camera;
    camera.position_m = {0.0, c.level_m + 3.0, 0.0};
    camera.pitch_deg = -6.0;
    camera.roll_deg = c.roll_deg;
    swell::View view = swell::viewOf(camera, kSize);
    if (c.reversedZ) {
        view.projection = reversedInfiniteProjection(camera.fovY_deg, double(kSize.x) / kSize.y, camera.near_m);
        view.depth = swell::DepthMode::Reversed;
    }
    return view;
}

Box cube(double level_m) { return boxBetween({2.5, level_m + 1.0, -27.0}, {5.5, level_m + 4.0, -24.0}, kCubeColor); }
Box wall(double level_m) { return boxBetween({-9.0, level_m + 0.5, -12.2}, {-3.0, level_m + 5.0, -12.0}, kWallColor); }

// The boxes in their own flat colour: all ambient, no sun.
void unlit(BoxRenderer& r)
{
    r.light.sun = glm::vec3(0.0f);
    r.light.sky = r.light.ground = glm::vec3(1.0f);
}

struct Pixels {
    std::vector<std::uint8_t> rgba;
    const std::uint8_t* at(int x, int y) const { return &rgba[(std::size_t(y) * kSize.x + std::size_t(x)) * 4]; }
    bool same(const Pixels& o, int x, int y) const
    {
        const std::uint8_t *a = at(x, y), *b = o.at(x, y);
        return a[0] == b[0] && a[1] == b[1] && a[2] == b[2] && a[3] == b[3];
    }
};

bool isRed(const std::uint8_t* p) { return p[0] > 110 && p[1] < 60 && p[2] < 60; }

// Where `boxes` alone cover the frame, each placed by `world` first.
std::vector<bool> coverage(const std::vector<Box>& boxes, const swell::View& view, const glm::dmat4& world)
{
    Target target(kSize, GL_RGBA8);
    BoxRenderer r;
    for (const Box& b : boxes)
        r.boxes.push_back({world * b.model, b.color});
    const float none[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    beginFrame(target, none, view.depth == swell::DepthMode::Reversed);
    r.draw(view.projection * view.view);
    const Pixels p{target.pixels()};
    std::vector<bool> mask(std::size_t(kSize.x) * kSize.y);
    for (int y = 0; y < kSize.y; ++y)
        for (int x = 0; x < kSize.x; ++x)
            mask[std::size_t(y) * kSize.x + std::size_t(x)] = p.at(x, y)[3] > 0;
    return mask;
}

// Whether any (all = false) or every (all = true) pixel of `mask` within
// `radius` pixels of (x, y) is set; pixels off the frame are skipped.
bool near(const std::vector<bool>& mask, int x, int y, int radius, bool all)
{
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
            const int u = x + dx, v = y + dy;
            if (u < 0 || v < 0 || u >= kSize.x || v >= kSize.y)
                continue;
            const bool in = mask[std::size_t(v) * kSize.x + std::size_t(u)];
            if (all && !in)
                return false;
            if (!all && in)
                return true;
        }
    return all;
}

// One view's checks; prints what failed. Returns whether all held.
bool check(const Config& c)
{
    const swell::Scene scene = mirrorScene(c.level_m);
    swell::Renderer renderer(scene);
    renderer.setWaveModel(std::make_shared<swell::FlatModel>());
    const swell::View view = checkView(c);
    BoxRenderer host;
    unlit(host);
    host.boxes = {cube(c.level_m), wall(c.level_m)};
    Target target(kSize, GL_RGBA8);
    beginFrame(target, kHostClear, c.reversedZ);
    host.draw(view.projection * view.view);
    const Pixels before{target.pixels()};

    renderer.advanceTo(10.0, view.eye_m());
    swell::DrawOptions options;
    options.geometry = &host;
    options.sky = false;
    renderer.draw(view, target.framebuffer(), options);
    const Pixels after{target.pixels()};

    const std::vector<bool> boxesMask = coverage(host.boxes, view, glm::dmat4(1.0));
    const glm::dmat4 mirror = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, c.level_m, 0.0)) *
                              glm::scale(glm::dmat4(1.0), glm::dvec3(1.0, -1.0, 1.0)) *
                              glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, -c.level_m, 0.0));
    const std::vector<bool> cubeMirror = coverage({cube(c.level_m)}, view, mirror);
    const glm::dmat4 inverse = glm::inverse(view.projection * view.view);

    int water = 0, reflected = 0, footprint = 0, stray = 0, unfilled = 0, changedHost = 0, changedSky = 0;
    for (int y = 0; y < kSize.y; ++y)
        for (int x = 0; x < kSize.x; ++x) {
            const std::size_t i = std::size_t(y) * kSize.x + std::size_t(x);
            const bool changed = !after.same(before, x, y);
            // The pixel's ray: up, level, or down to the water?
            const glm::dvec2 ndc((x + 0.5) / kSize.x * 2.0 - 1.0, (y + 0.5) / kSize.y * 2.0 - 1.0);
            const glm::dvec4 p = inverse * glm::dvec4(ndc, c.reversedZ ? 1.0 : -1.0, 1.0);
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
                ++stray;
            if (near(cubeMirror, x, y, 2, true)) {
                ++footprint;
                unfilled += !red;
            }
        }
    bool ok = true;
    auto expect = [&](bool holds, const std::string& what) {
        if (!holds)
            std::fprintf(stderr, "check %s: FAILED: %s\n", c.name, what.c_str());
        ok = ok && holds;
    };
    expect(water > kSize.x * kSize.y / 4, "the water was drawn (" + std::to_string(water) + " pixels)");
    expect(changedHost == 0, "the host's cube and wall hide the water behind them and are not drawn over (" +
                                 std::to_string(changedHost) + " of their pixels changed)");
    expect(changedSky == 0, "no host pixel above the horizon changes (" + std::to_string(changedSky) + " did)");
    expect(footprint > 100, "the cube's mirror image lies on the water (" + std::to_string(footprint) + " pixels)");
    expect(stray == 0, "the cube's reflection lies inside its mirror footprint within 2 px (" +
                           std::to_string(stray) + " red pixels outside)");
    expect(unfilled == 0, "the reflection fills the footprint (" + std::to_string(unfilled) + " of " +
                              std::to_string(footprint) + " not red)");
    const GLenum error = glGetError();
    expect(error == GL_NO_ERROR, "no GL error (" + std::to_string(error) + ")");
    if (ok)
        std::printf("check %s: ok (%d water pixels, %d of them the cube's reflection)\n", c.name, water, reflected);
    return ok;
}

} // namespace

int runChecks()
{
    const Config configs[] = {{"level", 0.0, false, 0.0},
                              {"rolled-30", 30.0, false, 0.0},
                              {"reversed-z", 0.0, true, 0.0},
                              {"sea-level-100m", 0.0, false, 100.0},
                              {"rolled-reversed-at-100m", 30.0, true, 100.0}};
    bool ok = true;
    for (const Config& c : configs)
        ok = check(c) && ok;
    return ok ? 0 : 3;
}

} // namespace host
