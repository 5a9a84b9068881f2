// The island's levels of detail (docs/RENDERING.md "The island's levels of
// detail"): the frame drawn with them against the same frame with the full
// grid in every pass (Renderer::setIslandTolerance(0)). The counters must
// show the triangles drop; the picture must stay within the stated
// tolerance of the full-detail one: every pixel found, within a pixel's
// reach, in the full-detail image (a silhouette moved by the half pixel the
// levels allow), and the whole image within a small mean.
#include "support/gl_test.h"
#include "support/golden.h"
#include "swell/camera.h"
#include "swell/debug.h"
#include "swell/renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

class IslandLod : public swell::test::GlTest {};

struct IslandLodDrawn {
    swell::Image image;
    long long worldTriangles = 0;
};

IslandLodDrawn draw(const swell::Scene& scene, const swell::Camera& camera, glm::ivec2 size, double tolerance_px)
{
    swell::Renderer renderer(scene);
    swell::RendererTesting::setIslandTolerance(renderer, tolerance_px);
    IslandLodDrawn d;
    d.image = renderer.renderImage(camera, 12.0, size);
    d.worldTriangles = renderer.counters().worldTriangles;
    return d;
}

// Pixels of `lod` with no pixel of `full` within one pixel (the 3x3 around
// it) whose every channel lies within maxChannel levels; the first few named in `where`.
int pixelsNotFoundNearby(const swell::Image& lod, const swell::Image& full, int maxChannel, std::string& where)
{
    int missing = 0;
    for (int y = 0; y < lod.height; ++y)
        for (int x = 0; x < lod.width; ++x) {
            const std::uint8_t* p = lod.pixel(x, y);
            bool found = false;
            for (int dy = -1; dy <= 1 && !found; ++dy)
                for (int dx = -1; dx <= 1 && !found; ++dx) {
                    const int qx = std::clamp(x + dx, 0, full.width - 1), qy = std::clamp(y + dy, 0, full.height - 1);
                    const std::uint8_t* q = full.pixel(qx, qy);
                    found = std::abs(p[0] - q[0]) <= maxChannel && std::abs(p[1] - q[1]) <= maxChannel &&
                            std::abs(p[2] - q[2]) <= maxChannel;
                }
            if (!found && ++missing <= 8)
                where += " (" + std::to_string(x) + ", " + std::to_string(y) + ")";
        }
    return missing;
}

void expectWithinTolerance(const IslandLodDrawn& lod, const IslandLodDrawn& full, const std::string& name)
{
    const swell::ImageDifference d = swell::compareImages(lod.image, full.image);
    std::string where;
    const int missing = pixelsNotFoundNearby(lod.image, full.image, 12, where);
    EXPECT_EQ(missing, 0) << name << ": pixels of the level-of-detail image found nowhere near in the full one:"
                          << where;
    std::printf("%s: %lld triangles of the world drawn, %lld with the full grid\n", name.c_str(), lod.worldTriangles,
                full.worldTriangles);
    EXPECT_LE(d.meanChannel, 0.05) << name;
    if (missing != 0 || d.meanChannel > 0.05) {
        ADD_FAILURE() << name << ": max channel difference " << d.maxChannel << ", mean " << d.meanChannel
                      << "\n  levels of detail: " << swell::test::saveTestImage(lod.image, name + ".actual")
                      << "\n  full grid:        " << swell::test::saveTestImage(full.image, name + ".full")
                      << "\n  diff:             " << swell::test::saveTestImage(d.diff, name + ".diff");
    }
}

// The default frame at the benchmark's size: the island 1 km and more away
// takes coarser levels in its deep-water rim in every pass, and in the
// reduced passes more of it: a third of the triangles or fewer (exact:
// 50744 of 157584 when written).
TEST_F(IslandLod, TheDefaultFrameDrawsAThirdOfTheTrianglesAndLooksTheSame)
{
    const swell::Scene scene = swell::defaultScene();
    const swell::Camera camera = swell::cameraAt(scene.camera, 12.0);
    const IslandLodDrawn full = draw(scene, camera, {1280, 720}, 0.0);
    const IslandLodDrawn lod = draw(scene, camera, {1280, 720}, 0.5);
    EXPECT_LE(lod.worldTriangles * 3, full.worldTriangles)
        << lod.worldTriangles << " triangles of the world drawn, " << full.worldTriangles << " at full detail";
    expectWithinTolerance(lod, full, "island_lod_default");
}

// Closer, 250 m from the island's box: the picture still matches, and
// the counters still drop.
TEST_F(IslandLod, CloserToTheIslandThePictureStillMatches)
{
    const swell::Scene scene = swell::defaultScene();
    swell::Camera camera = swell::cameraAt(scene.camera, 12.0);
    camera.position_m = {-700.0, 12.0, -750.0}; // 250 m from the island's edge, looking at its peak
    camera.yaw_deg = 0.0;
    camera.pitch_deg = 0.0;
    const IslandLodDrawn full = draw(scene, camera, {640, 360}, 0.0);
    const IslandLodDrawn lod = draw(scene, camera, {640, 360}, 0.5);
    EXPECT_LE(lod.worldTriangles * 2, full.worldTriangles);
    expectWithinTolerance(lod, full, "island_lod_shore");
}

} // namespace
