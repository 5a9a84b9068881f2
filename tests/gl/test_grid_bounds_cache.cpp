// The water grid's tile bounds are computed once per grid scale and morph
// band, not once per frame: they hold wherever the grid's centre snaps, so a
// camera flying level across hundreds of snaps reuses them, and whatever the
// waves' reach, which pads them as they are tested. (That they hold is
// test_grid_culling's job, which also culls from a camera elsewhere first.)
// The blocks' quadtree chooses the tiles a test of each tile alone would.
// The bounds hold every vertex's place, on the CPU, without the waves.
#include "core/grid_tiles.h"
#include "render/water_grid.h"
#include "support/gl_test.h"
#include "swell/scene/grid.h"
#include "swell/scene/scene.h"

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <sstream>
#include <glm/ext/matrix_transform.hpp>

namespace {

class GridBoundsCache : public swell::test::GlTest {};

// Each tile's bounds, found once for a placement, hold its corners' snapped
// places (gridPoint) for the camera anywhere in the same scale and morph
// band: other centres, every morph across the band. Cameras from 6 m to
// 300 m over both layouts, no waves (reach 0), so nothing but the bounds'
// own margin (snapping, float slack) stands between a vertex and the edge.
// The test the drawn-triangle culling tests (test_grid_culling) cannot make:
// their storm's reach pads the bounds by metres.
TEST(GridBounds, HoldEveryVertexForEveryCentreAndMorphInTheBand)
{
    for (const swell::GridLayout layout : {swell::GridLayout::Geometric, swell::GridLayout::Paper}) {
        swell::Scene scene = swell::defaultScene();
        scene.grid.layout = layout;
        const swell::GridShape shape = swell::gridShapeFor(scene.grid, scene.camera);
        const swell::detail::TiledGrid grid = swell::detail::tileGrid(shape.cells, swell::detail::WaterGrid::kTileCells,
                                                                                  swell::detail::WaterGrid::kBlockTiles);
        int outside = 0, checked = 0;
        for (const double height_m : {6.0, 14.0, 20.0, 30.0, 46.0, 60.0, 100.0, 300.0}) {
            const swell::GridPlacement placement = swell::placeGrid(shape, {3.3, height_m, -7.9});
            const swell::detail::GridBounds bounds = swell::detail::gridBounds(shape, placement, grid, swell::WaveReach{});
            const int band = swell::detail::morphBand(placement.morph);
            const double lo = band == 0 ? 0.0 : double(band - 1) / swell::detail::kMorphBands;
            const double hi = band == 0 ? 0.0 : double(band) / swell::detail::kMorphBands;
            for (const glm::dvec2 camera_m : {glm::dvec2(3.3, -7.9), glm::dvec2(-511.37, 92.06), glm::dvec2(1e4 / 3.0, -77.7)})
                for (const double morph : {lo, 0.5 * (lo + hi), hi}) {
                    swell::GridPlacement moved = swell::placeGrid(shape, {camera_m.x, height_m, camera_m.y});
                    ASSERT_EQ(moved.scale, placement.scale);
                    moved.morph = morph;
                    for (std::size_t t = 0; t < grid.tiles.size(); ++t) {
                        const swell::detail::GridTile& tile = grid.tiles[t];
                        const swell::detail::Bounds& box = bounds.tiles[t];
                        for (const int i : {tile.i0, tile.i1})
                            for (const int j : {tile.j0, tile.j1}) {
                                const glm::dvec2 p = swell::gridPoint(shape, moved, i, j).offset_m;
                                ++checked;
                                if (p.x < box.lo.x || p.x > box.hi.x || p.y < box.lo.z || p.y > box.hi.z) {
                                    if (outside++ < 5)
                                        ADD_FAILURE() << "vertex (" << i << ", " << j << ") at (" << p.x << ", " << p.y
                                                      << ") m outside its tile's bounds x " << box.lo.x << ".." << box.hi.x
                                                      << ", z " << box.lo.z << ".." << box.hi.z << " (camera " << height_m
                                                      << " m up, morph " << morph << ")";
                                }
                            }
                    }
                }
        }
        EXPECT_EQ(outside, 0) << "of " << checked << " vertices checked";
    }
}

TEST_F(GridBoundsCache, ComputedOncePerScaleAndMorphBandNotPerSnap)
{
    const swell::Scene scene = swell::defaultScene();
    const swell::GridShape shape = swell::gridShapeFor(scene.grid, scene.camera);
    swell::detail::WaterGrid grid;
    grid.build(shape);
    const swell::WaveReach reach{1.0, 0.5};
    const glm::dmat4 viewProj = glm::perspective(1.0, 16.0 / 9.0, 0.1, 2.0e4) *
                                glm::lookAt(glm::dvec3(0.0, 6.0, 0.0), glm::dvec3(0.0, 5.0, -10.0), glm::dvec3(0.0, 1.0, 0.0));
    auto cullAt = [&](glm::dvec3 camera_m) {
        const swell::GridPlacement placement = swell::placeGrid(shape, camera_m);
        grid.cull(shape, placement, reach, viewProj, false, placement.center_m - glm::dvec2(camera_m.x, camera_m.z));
        return placement;
    };
    // 6 m up, flying 37 cm a frame for 200 frames: a new grid centre every frame.
    int snaps = 0;
    glm::dvec2 lastCenter(1e30);
    for (int frame = 0; frame < 200; ++frame) {
        const swell::GridPlacement placement = cullAt({0.37 * frame, 6.0, -0.11 * frame});
        snaps += placement.center_m != lastCenter ? 1 : 0;
        lastCenter = placement.center_m;
    }
    EXPECT_EQ(snaps, 200);
    EXPECT_EQ(grid.boundsComputed(), 1);
    // Climbing through the morph from scale 1 to 2 (13.2 .. 47 m) 1 cm a
    // frame changes them once per morph band, not per frame.
    const long long before = grid.boundsComputed();
    for (double h = 13.0; h <= 48.0; h += 0.01)
        cullAt({5.0, h, 3.0});
    EXPECT_EQ(grid.boundsComputed() - before, 1 + swell::detail::kMorphBands);
    // Another reach every frame (a spectral sea's, frame by frame): the same bounds.
    const long long atReach = grid.boundsComputed();
    for (int frame = 0; frame < 50; ++frame) {
        const swell::GridPlacement placement = swell::placeGrid(shape, {5.0, 6.0, 3.0});
        grid.cull(shape, placement, {1.0 + 0.1 * frame, 0.5 + 0.05 * frame}, viewProj, false, placement.center_m - glm::dvec2(5.0, 3.0));
    }
    EXPECT_EQ(grid.boundsComputed() - atReach, 1) << "the reach must pad the bounds, not rebuild them";
}

// The tiles chosen through the blocks' quadtree are those whose own box
// reaches the frustum, for cameras low and high, in every direction, and
// with reaches from calm to a storm's: every one of them, and no other for
// a calm sea's reach; where the reach dwarfs a node's tiles (near the
// camera in a storm) the node is drawn whole, a few more triangles than
// testing each tile would draw. The quadtree tests fewer boxes.
TEST_F(GridBoundsCache, TheQuadtreeChoosesTheTilesATestOfEachWould)
{
    using namespace swell::detail;
    const swell::Scene scene = swell::defaultScene();
    const swell::GridShape shape = swell::gridShapeFor(scene.grid, scene.camera);
    WaterGrid grid;
    grid.build(shape);
    const TiledGrid tiles = tileGrid(shape.cells, WaterGrid::kTileCells, WaterGrid::kBlockTiles);
    long long tested = 0, tiled = 0, expectedIndices = 0, chosenIndices = 0;
    for (const swell::WaveReach reach : {swell::WaveReach{0.3, 0.2}, swell::WaveReach{12.0, 8.0}, swell::WaveReach{80.0, 80.0}})
        for (const glm::dvec3 eye : {glm::dvec3(3.0, 2.0, -7.0), glm::dvec3(-40.0, 30.0, 11.0), glm::dvec3(0.5, 300.0, 0.5)}) {
            const glm::dvec3 origin(eye.x, 0.0, eye.z);
            const swell::GridPlacement placement = swell::placeGrid(shape, eye);
            const glm::dvec2 centre = placement.center_m - glm::dvec2(origin.x, origin.z);
            // Each tile's box alone, found once for every direction of this
            // eye: it depends on the eye and the reach only, and finding it
            // is most of the test's work.
            std::vector<Bounds> boxes;
            for (const GridTile& tile : tiles.tiles) {
                Bounds box = tileBounds(shape, placement, tile, reach);
                box.lo += glm::dvec3(centre.x, 0.0, centre.y);
                box.hi += glm::dvec3(centre.x, 0.0, centre.y);
                boxes.push_back(box);
            }
            for (double yaw = 0.0; yaw < 360.0; yaw += 45.0)
                for (const double pitch : {-5.0, -40.0}) {
                    const glm::dvec3 direction(std::sin(glm::radians(yaw)) * std::cos(glm::radians(pitch)),
                                               std::sin(glm::radians(pitch)),
                                               -std::cos(glm::radians(yaw)) * std::cos(glm::radians(pitch)));
                    const glm::dmat4 viewProj = glm::perspective(0.9, 16.0 / 9.0, 0.1, 2.0e4) *
                                                glm::lookAt(eye - origin, eye - origin + direction, glm::dvec3(0.0, 1.0, 0.0));
                    grid.cull(shape, placement, reach, viewProj, false, centre);
                    tested += grid.boxesTested();
                    // Each tile alone, in the buffer's order.
                    const Frustum frustum = frustumPlanes(viewProj, false);
                    std::vector<std::uint32_t> expected;
                    for (size_t t = 0; t < tiles.tiles.size(); ++t) {
                        const GridTile& tile = tiles.tiles[t];
                        if (frustumContains(frustum, boxes[t]) != Containment::Outside)
                            expected.insert(expected.end(), tiles.indices.begin() + tile.firstIndex,
                                            tiles.indices.begin() + tile.firstIndex + tile.indexCount);
                    }
                    tiled += (long long)tiles.blocks.size() + (long long)tiles.tiles.size();
                    const std::vector<std::uint32_t> chosen = grid.chosenIndices();
                    std::ostringstream where;
                    where << "eye " << eye.x << ", " << eye.y << ", " << eye.z << ", yaw " << yaw << ", pitch " << pitch
                          << ", reach " << reach.vertical_m;
                    if (reach.horizontal_m < 1.0) {
                        ASSERT_EQ(chosen, expected) << where.str();
                    } else {
                        // Both in the buffer's order: every expected triangle among the chosen.
                        size_t k = 0;
                        for (size_t i = 0; i < chosen.size() && k < expected.size(); i += 3)
                            if (std::equal(chosen.begin() + std::ptrdiff_t(i), chosen.begin() + std::ptrdiff_t(i + 3),
                                           expected.begin() + std::ptrdiff_t(k)))
                                k += 3;
                        ASSERT_EQ(k, expected.size()) << "a tile that reaches the view left out: " << where.str();
                    }
                    expectedIndices += (long long)expected.size();
                    chosenIndices += (long long)chosen.size();
                }
        }
    EXPECT_LT(tested * 2, tiled) << "the quadtree should test well under half the boxes of testing every tile";
    EXPECT_LE(double(chosenIndices), 1.03 * double(expectedIndices)) << "nodes drawn whole add at most 3% of the triangles";
}

} // namespace
