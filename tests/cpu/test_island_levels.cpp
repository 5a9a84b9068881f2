// The island's levels of detail (assets/island_levels.h): each tile's
// stated error is the largest vertical distance between the triangles it
// draws and the full grid's, its tiles hold each of its cells once, the
// skirts reach below the gap between any two levels' edges, and the level
// chosen for a view is the coarsest whose error projects within the
// tolerance.
#include "assets/island_levels.h"
#include "assets/mesh_data.h"

#include <glm/common.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

namespace {

using namespace swell::detail;

// The built-in island's parameters (render/world.h).
constexpr double kSize_m = 1400.0, kPeak_m = 70.0;
constexpr int kResolution = 192, kTileCells = 16;

const MeshData& island()
{
    static const MeshData mesh = makeIsland(kSize_m, kPeak_m, kResolution);
    return mesh;
}

const IslandLevels& levels()
{
    static const IslandLevels l = makeIslandLevels(island(), kResolution, kTileCells);
    return l;
}

TEST(IslandLevels, FiveLevelsEachAQuarterOfTheTrianglesOfTheFinerOne)
{
    ASSERT_EQ(levels().levels.size(), 5u);
    for (std::size_t k = 0; k < 5; ++k) {
        const IslandLevel& level = levels().levels[k];
        EXPECT_EQ(level.step, 1 << k);
        const int cells = kResolution / level.step;
        EXPECT_EQ(level.triangles, std::uint32_t(2 * cells * cells)) << "level " << k;
        EXPECT_EQ(level.tiles.size(), std::size_t((kResolution / kTileCells) * (kResolution / kTileCells)));
    }
    // The finest level draws exactly the island's own triangles.
    EXPECT_EQ(levels().levels[0].triangles * 3, island().indices.size());
    // The full grid's vertices come first, unchanged.
    for (std::size_t v = 0; v < island().vertices.size(); ++v)
        ASSERT_EQ(levels().mesh.vertices[v].position, island().vertices[v].position);
}

// The error stated for each level, recomputed from the triangles its index
// buffer draws: for every vertex of the full grid, the height of the
// level's triangle above or below it (found by a point-in-triangle test in
// the horizontal plane, not by the level builder's own cell arithmetic).
// The full grid is linear between its vertices and every level's edges run
// along its edges, so the largest difference at the vertices is the
// largest anywhere.
TEST(IslandLevels, EachTilesErrorIsTheLargestHeightDifferenceOfItsTriangles)
{
    const MeshData& grid = island();
    const std::vector<std::uint32_t>& indices = levels().mesh.indices;
    const int n = kResolution;
    const double cell_m = kSize_m / n;
    for (std::size_t k = 0; k < levels().levels.size(); ++k) {
        const IslandLevel& level = levels().levels[k];
        std::vector<double> coarse(grid.vertices.size(), std::nan(""));
        std::vector<glm::vec3> coarseColor(grid.vertices.size());
        for (const IslandTile& tile : level.tiles)
            for (std::uint32_t t = tile.cells.first; t < tile.cells.first + tile.cells.count; t += 3) {
                const glm::vec3 a = grid.vertices[indices[t]].position, b = grid.vertices[indices[t + 1]].position,
                                c = grid.vertices[indices[t + 2]].position;
                const double lo_x = std::min({a.x, b.x, c.x}), hi_x = std::max({a.x, b.x, c.x});
                const double lo_z = std::min({a.z, b.z, c.z}), hi_z = std::max({a.z, b.z, c.z});
                const int i0 = int(std::floor((lo_x + 0.5 * kSize_m) / cell_m + 0.5));
                const int i1 = int(std::floor((hi_x + 0.5 * kSize_m) / cell_m + 0.5));
                const int j0 = int(std::floor((lo_z + 0.5 * kSize_m) / cell_m + 0.5));
                const int j1 = int(std::floor((hi_z + 0.5 * kSize_m) / cell_m + 0.5));
                const double det = double(b.x - a.x) * (c.z - a.z) - double(c.x - a.x) * (b.z - a.z);
                ASSERT_NE(det, 0.0);
                for (int j = j0; j <= j1; ++j)
                    for (int i = i0; i <= i1; ++i) {
                        const glm::vec3 p = grid.vertices[std::size_t(j * (n + 1) + i)].position;
                        const double u = (double(p.x - a.x) * (c.z - a.z) - double(c.x - a.x) * (p.z - a.z)) / det;
                        const double v = (double(b.x - a.x) * (p.z - a.z) - double(p.x - a.x) * (b.z - a.z)) / det;
                        if (u < -1e-6 || v < -1e-6 || u + v > 1.0 + 1e-6)
                            continue;
                        coarse[std::size_t(j * (n + 1) + i)] = a.y + u * (b.y - a.y) + v * (c.y - a.y);
                        const glm::vec3 ca = grid.vertices[indices[t]].color, cb = grid.vertices[indices[t + 1]].color,
                                        cc = grid.vertices[indices[t + 2]].color;
                        coarseColor[std::size_t(j * (n + 1) + i)] = ca + float(u) * (cb - ca) + float(v) * (cc - ca);
                    }
            }
        for (std::size_t v = 0; v < grid.vertices.size(); ++v)
            ASSERT_FALSE(std::isnan(coarse[v])) << "level " << k << ": vertex " << v << " under no triangle";
        // Each tile's own, over the vertices of its square: the height's,
        // or where a colour moved more than 0.02, the cell's diagonal.
        const int tiles = levels().tilesPerSide;
        double largest = 0.0;
        int colorTiles = 0;
        for (int t = 0; t < tiles * tiles; ++t) {
            double own = 0.0;
            bool colorMoved = false;
            for (int j = (t / tiles) * kTileCells; j <= (t / tiles + 1) * kTileCells; ++j)
                for (int i = (t % tiles) * kTileCells; i <= (t % tiles + 1) * kTileCells; ++i) {
                    const std::size_t v = std::size_t(j * (n + 1) + i);
                    own = std::max(own, std::abs(double(grid.vertices[v].position.y) - coarse[v]));
                    const glm::vec3 off = glm::abs(coarseColor[v] - grid.vertices[v].color);
                    colorMoved = colorMoved || std::max({off.x, off.y, off.z}) > 0.02f;
                }
            if (colorMoved)
                own = std::max(own, std::sqrt(2.0) * level.step * cell_m);
            colorTiles += colorMoved;
            largest = std::max(largest, own);
            EXPECT_NEAR(level.tiles[std::size_t(t)].error_m, own, 1e-3) << "level " << k << ", tile " << t;
        }
        EXPECT_NEAR(level.error_m, largest, 1e-3) << "level " << k;
        // The beach runs through some tiles at every coarser level, not through all.
        if (k > 0) {
            EXPECT_GT(colorTiles, 0) << "level " << k;
            EXPECT_LT(colorTiles, tiles * tiles) << "level " << k;
        }
        if (k == 0)
            EXPECT_EQ(level.error_m, 0.0);
        else
            EXPECT_GT(level.error_m, levels().levels[k - 1].error_m) << "level " << k;
    }
    // The island's relief lies in its middle: the tiles on its rim, in
    // deep water, are smooth at every level (their coarsest within 10 cm),
    // which is what lets a far view draw them coarse.
    const IslandLevel& coarsest = levels().levels.back();
    EXPECT_LT(coarsest.tiles.front().error_m, 0.1);
    EXPECT_LT(coarsest.tiles.back().error_m, 0.1);
    EXPECT_GT(coarsest.error_m, 5.0);
}

// Where a tile at one level meets a neighbour at another, each side's
// skirt hangs from its own level's edge down below every other level's
// edge along that side: the two skirts together fill the gap between the
// edges, whichever lies higher. Read from the skirts' own vertices.
TEST(IslandLevels, SkirtsReachBelowEveryOtherLevelsEdge)
{
    const std::vector<MeshVertex>& v = levels().mesh.vertices;
    const std::vector<std::uint32_t>& indices = levels().mesh.indices;
    const std::uint32_t gridVertices = std::uint32_t(island().vertices.size());
    const int tiles = levels().tilesPerSide;
    int sides = 0;
    for (int t = 0; t < tiles * tiles; ++t)
        for (int side = 0; side < kTileSides; ++side) {
            const int across = levels().neighbours[std::size_t(t)][std::size_t(side)];
            // Per level: the edge's points (position along the side, height) and the skirt's depth.
            std::vector<std::vector<std::pair<double, double>>> edges;
            std::vector<double> depths;
            for (const IslandLevel& level : levels().levels) {
                const IndexRange& skirt = level.tiles[std::size_t(t)].skirts[std::size_t(side)];
                ASSERT_EQ(skirt.count == 0, across < 0);
                if (across < 0)
                    continue;
                std::vector<std::pair<double, double>> edge;
                double depth = -1.0;
                for (std::uint32_t i = skirt.first; i < skirt.first + skirt.count; ++i) {
                    const glm::vec3 p = v[indices[i]].position;
                    const double along = side < 2 ? p.z : p.x;
                    if (indices[i] < gridVertices) {
                        edge.emplace_back(along, p.y);
                    } else {
                        // A hanging vertex: the same place as the edge's, lower.
                        bool below = false;
                        for (const auto& [a, h] : edge)
                            if (a == along) {
                                const double d = h - p.y;
                                EXPECT_GT(d, 0.0);
                                EXPECT_TRUE(depth < 0.0 || std::abs(d - depth) < 1e-3);
                                depth = d;
                                below = true;
                            }
                        EXPECT_TRUE(below || edge.size() < 2);
                    }
                }
                std::sort(edge.begin(), edge.end());
                edge.erase(std::unique(edge.begin(), edge.end()), edge.end());
                edges.push_back(edge);
                depths.push_back(depth);
            }
            if (across < 0)
                continue;
            ++sides;
            auto heightOn = [](const std::vector<std::pair<double, double>>& edge, double along) {
                for (std::size_t i = 0; i + 1 < edge.size(); ++i)
                    if (along >= edge[i].first && along <= edge[i + 1].first) {
                        const double f = (along - edge[i].first) / (edge[i + 1].first - edge[i].first);
                        return edge[i].second + f * (edge[i + 1].second - edge[i].second);
                    }
                return std::nan("");
            };
            for (std::size_t a = 0; a < edges.size(); ++a)
                for (std::size_t b = 0; b < edges.size(); ++b)
                    for (const auto& [along, h] : edges[0]) { // the full grid's points along the side
                        (void)h;
                        const double ya = heightOn(edges[a], along), yb = heightOn(edges[b], along);
                        ASSERT_FALSE(std::isnan(ya) || std::isnan(yb));
                        EXPECT_LE(ya - depths[a], yb + 1e-4) << "tile " << t << ", side " << side << ": level " << a
                                                            << "'s skirt ends above level " << b << "'s edge";
                    }
        }
    EXPECT_EQ(sides, 4 * tiles * (tiles - 1)); // every side between two tiles, from both
}

// Every cell of a level lies in exactly one tile, and inside its box.
TEST(IslandLevels, TilesHoldEachCellOnceAndEverythingInsideTheirBoxes)
{
    for (const IslandLevel& level : levels().levels) {
        std::set<std::pair<std::uint32_t, std::uint32_t>> cells;
        const std::vector<std::uint32_t>& indices = levels().mesh.indices;
        for (std::size_t t = 0; t < level.tiles.size(); ++t) {
            const IslandTile& tile = level.tiles[t];
            const glm::vec3 lo = levels().boxLo[t], hi = levels().boxHi[t];
            std::vector<IndexRange> ranges(tile.skirts.begin(), tile.skirts.end());
            ranges.push_back(tile.cells);
            for (const IndexRange& range : ranges)
                for (std::uint32_t i = range.first; i < range.first + range.count; ++i) {
                    const glm::vec3 p = levels().mesh.vertices[indices[i]].position;
                    EXPECT_TRUE(p.x >= lo.x && p.y >= lo.y && p.z >= lo.z && p.x <= hi.x && p.y <= hi.y && p.z <= hi.z);
                }
            for (std::uint32_t i = tile.cells.first; i < tile.cells.first + tile.cells.count; i += 3)
                cells.insert({indices[i], indices[i + 2]});
        }
        EXPECT_EQ(cells.size(), std::size_t(level.triangles)) << "step " << level.step;
    }
}

TEST(IslandLevels, TheCoarsestLevelWithinTheToleranceIsChosen)
{
    const double focal_px = 623.5; // 720 pixels high, 60 degrees
    for (double distance_m : {1.0, 50.0, 200.0, 600.0, 1000.0, 3000.0, 20000.0})
        for (double tolerance_px : {0.25, 0.5, 1.0, 4.0}) {
            for (std::size_t t = 0; t < levels().boxLo.size(); ++t) {
                const std::size_t k = islandTileLevel(levels(), t, distance_m, focal_px, tolerance_px);
                const auto error = [&](std::size_t level) { return levels().levels[level].tiles[t].error_m; };
                EXPECT_TRUE(k == 0 || projectedError_px(error(k), distance_m, focal_px) <= tolerance_px);
                for (std::size_t coarser = k + 1; coarser < levels().levels.size(); ++coarser)
                    EXPECT_GT(projectedError_px(error(coarser), distance_m, focal_px), tolerance_px)
                        << distance_m << " m, " << tolerance_px << " px, tile " << t;
            }
        }
    // The peak's tile (the most relief): far away the coarsest, close by the
    // full grid, and a tolerance of 0 the full grid anywhere.
    const std::size_t middle = std::size_t(levels().tilesPerSide / 2 * (levels().tilesPerSide + 1));
    EXPECT_EQ(islandTileLevel(levels(), middle, 1e6, focal_px, 0.5), levels().levels.size() - 1);
    EXPECT_EQ(islandTileLevel(levels(), middle, 1000.0, focal_px, 0.5), 0u);
    EXPECT_EQ(islandTileLevel(levels(), middle, 0.0, focal_px, 0.5), 0u);
    EXPECT_EQ(islandTileLevel(levels(), middle, 1e6, focal_px, 0.0), 0u);
    // A rim tile in deep water: the coarsest already from 1 km.
    EXPECT_EQ(islandTileLevel(levels(), 0, 1000.0, focal_px, 0.5), levels().levels.size() - 1);
    // Half the pixels a radian (the reduced reflection pass) allows a level
    // at least as coarse at the same distance.
    for (double distance_m : {200.0, 600.0, 1000.0, 3000.0})
        for (std::size_t t = 0; t < levels().boxLo.size(); ++t)
            EXPECT_GE(islandTileLevel(levels(), t, distance_m, 0.5 * focal_px, 0.5),
                      islandTileLevel(levels(), t, distance_m, focal_px, 0.5));
}

TEST(IslandLevels, TheErrorOnScreenShrinksWithDistance)
{
    EXPECT_DOUBLE_EQ(projectedError_px(2.0, 1000.0, 600.0), 1.2);
    EXPECT_DOUBLE_EQ(projectedError_px(2.0, 2000.0, 600.0), 0.6);
    EXPECT_TRUE(std::isinf(projectedError_px(2.0, 0.0, 600.0)));
    EXPECT_EQ(projectedError_px(0.0, 0.0, 600.0), 0.0);
}

TEST(IslandLevels, AGridThatTilesDoNotDivideIsRefused)
{
    EXPECT_ANY_THROW(makeIslandLevels(island(), kResolution, 25));
    EXPECT_ANY_THROW(makeIslandLevels(makeIsland(kSize_m, kPeak_m, 96), kResolution, kTileCells));
}

} // namespace
