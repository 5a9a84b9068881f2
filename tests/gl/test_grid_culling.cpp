// The water grid's tiles outside the view are left out of the draw, and only
// those: every triangle the GPU would place even partly inside the view
// frustum is among the triangles drawn, for both layouts and many cameras.
#include "support/gl_test.h"
#include "support/param_names.h"
#include "swell/debug.h"
#include "swell/renderer.h"

#include <epoxy/gl.h>
#include <glm/vec4.hpp>

#include "swell/gl/handle.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <ostream>
#include <set>
#include <sstream>
#include <string>

namespace {

struct GridCullingCase {
    swell::GridLayout layout;
    glm::dvec3 position_m;
    double yaw_deg, pitch_deg;
    // Steep, tall waves by default: their sideways and vertical reach must be
    // in the bounds. A calm sea leaves the bounds little margin beyond the grid's own.
    double windSpeed_mps = 20.0;
};

// A number in a test name: digits and letters only ("m" for minus, "p" for
// the point), e.g. -250.3 -> "m250p3".
std::string nameNumber(double x)
{
    std::ostringstream text;
    text << x;
    std::string s;
    for (char c : text.str())
        if (c != '+')
            s += c == '-' ? 'm' : c == '.' ? 'p' : c;
    return s;
}

// What the name (caseName) leaves out, the camera's place: GetParam() is
// otherwise the struct's bytes, its padding included, which differ from
// build to build.
void PrintTo(const GridCullingCase& c, std::ostream* os)
{
    *os << "camera at (" << c.position_m.x << ", " << c.position_m.y << ", " << c.position_m.z << ") m";
}

// The test's name: layout, camera height, yaw, pitch and wind (every case
// differs in one of them), e.g. Geometric_H6_Yaw0_Pitchm5_Wind20.
std::string caseName(const GridCullingCase& c)
{
    return swell::paramName(c.layout) + "_H" + nameNumber(c.position_m.y) + "_Yaw" + nameNumber(c.yaw_deg) + "_Pitch" +
           nameNumber(c.pitch_deg) + "_Wind" + nameNumber(c.windSpeed_mps);
}

class GridCulling : public swell::test::GlTest, public testing::WithParamInterface<GridCullingCase> {};

// Bits of the clip-space planes a point lies outside of.
unsigned outcode(const glm::dvec4& c)
{
    return (c.x < -c.w ? 1u : 0u) | (c.x > c.w ? 2u : 0u) | (c.y < -c.w ? 4u : 0u) | (c.y > c.w ? 8u : 0u) |
           (c.z < -c.w ? 16u : 0u) | (c.z > c.w ? 32u : 0u);
}

TEST_P(GridCulling, EveryTriangleThatReachesTheViewIsDrawn)
{
    const GridCullingCase c = GetParam();
    swell::Scene scene = swell::defaultScene();
    scene.objects.clear();
    scene.showTerrain = false;
    scene.grid.layout = c.layout;
    scene.grid.resolution = 129;
    scene.sea.wind->windSpeed_mps = c.windSpeed_mps;
    swell::Renderer renderer(scene);
    swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    camera.position_m = c.position_m;
    camera.yaw_deg = c.yaw_deg;
    camera.pitch_deg = c.pitch_deg;
    const glm::ivec2 size(320, 180);

    const int count = swell::RendererTesting::waterVertexCount(renderer);
    swell::gl::Buffer buffer = swell::gl::Buffer::create();
    glNamedBufferStorage(buffer.id(), GLsizeiptr(count) * 8 * 4, nullptr, 0);
    std::vector<std::uint32_t> drawn;
    // The renderer first culls for a camera elsewhere, 2 m above the water
    // (another grid centre, and the smallest grid scale): bounds kept from
    // that frame must not be reused for the higher cameras' larger grids.
    swell::Camera elsewhere = camera;
    elsewhere.position_m += glm::dvec3(317.0, 0.0, -733.0);
    elsewhere.position_m.y = 2.0;
    swell::RendererTesting::captureWaterVertices(renderer, elsewhere, 12.0, buffer.id(), size, &drawn);
    swell::RendererTesting::captureWaterVertices(renderer, camera, 12.0, buffer.id(), size, &drawn);
    std::vector<float> data(size_t(count) * 8);
    glGetNamedBufferSubData(buffer.id(), 0, GLsizeiptr(data.size() * 4), data.data());

    const glm::dvec3 origin(camera.position_m.x, 0.0, camera.position_m.z);
    const glm::dmat4 viewProj = camera.projection(double(size.x) / size.y) * camera.viewRelativeTo(origin);
    std::vector<unsigned> codes(static_cast<size_t>(count));
    for (size_t v = 0; v < codes.size(); ++v) {
        const float* p = &data[v * 8 + 2];
        codes[v] = outcode(viewProj * glm::dvec4(p[0], p[1], p[2], 1.0));
    }
    // Drawn triangles, as sorted vertex triples.
    std::set<std::array<std::uint32_t, 3>> drawnSet;
    for (size_t t = 0; t + 2 < drawn.size(); t += 3) {
        std::array<std::uint32_t, 3> tri{drawn[t], drawn[t + 1], drawn[t + 2]};
        std::sort(tri.begin(), tri.end());
        drawnSet.insert(tri);
    }
    // Every cell's two triangles, whichever diagonal the renderer chose.
    const auto lines = std::uint32_t(std::lround(std::sqrt(double(count))));
    int visibleCells = 0, missing = 0;
    for (std::uint32_t j = 0; j + 1 < lines; ++j)
        for (std::uint32_t i = 0; i + 1 < lines; ++i) {
            const std::uint32_t a = j * lines + i, b = a + 1, cc = a + lines, d = cc + 1;
            if (codes[a] & codes[b] & codes[cc] & codes[d])
                continue; // wholly outside one plane: may be culled
            ++visibleCells;
            const bool found = drawnSet.count({a, b, d}) + drawnSet.count({a, cc, d}) + drawnSet.count({a, b, cc}) +
                                   drawnSet.count({b, cc, d}) >= 2;
            missing += found ? 0 : 1;
        }
    EXPECT_GT(visibleCells, 100);
    EXPECT_EQ(missing, 0) << "cells reaching the view but not drawn";
    // Culling must cull: no camera here sees three quarters of the grid around it.
    const size_t triangles = 2 * size_t(lines - 1) * (lines - 1);
    EXPECT_LT(drawnSet.size(), triangles * 3 / 4) << "too few tiles culled";
}

INSTANTIATE_TEST_SUITE_P(
    Views, GridCulling,
    testing::Values(GridCullingCase{swell::GridLayout::Geometric, {0.0, 6.0, 0.0}, 0.0, -5.0},
                    GridCullingCase{swell::GridLayout::Geometric, {123.4, 2.0, -56.7}, 137.0, -1.0},
                    GridCullingCase{swell::GridLayout::Geometric, {-40.0, 60.0, 10.0}, -60.0, -35.0},
                    GridCullingCase{swell::GridLayout::Geometric, {5.0e5, 12.0, -3.0e5}, 250.0, 10.0},
                    // Cameras in the morph between scales: vertices between two lattices.
                    GridCullingCase{swell::GridLayout::Geometric, {17.0, 25.0, -33.0}, 75.0, -15.0},
                    GridCullingCase{swell::GridLayout::Geometric, {-250.3, 4.0, 71.9}, -120.0, -3.0},
                    GridCullingCase{swell::GridLayout::Geometric, {17.0, 25.0, -33.0}, 75.0, -15.0, 2.0},
                    GridCullingCase{swell::GridLayout::Geometric, {-250.3, 4.0, 71.9}, -120.0, -3.0, 2.0},
                    GridCullingCase{swell::GridLayout::Geometric, {31.0, 40.0, 7.0}, 10.0, -45.0, 2.0},
                    GridCullingCase{swell::GridLayout::Paper, {0.0, 6.0, 0.0}, 45.0, -5.0},
                    GridCullingCase{swell::GridLayout::Paper, {-7.0, 25.0, 3.0}, 200.0, -50.0}),
    [](const testing::TestParamInfo<GridCullingCase>& view) { return caseName(view.param); });

} // namespace
