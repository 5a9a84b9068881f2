// The built-in island's levels of detail (docs/RENDERING.md "The island's
// levels of detail"): the heightfield's grid cut into square tiles, each
// tile drawn at the full grid's every 2^k-th vertex with k chosen per tile
// and per pass from its own exact error's size on screen, and skirts that
// hide the cracks where two tiles of different levels meet.
#pragma once

#include "assets/mesh_data.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace swell::detail {

struct IndexRange {
    std::uint32_t first = 0; // into IslandLevels::mesh.indices
    std::uint32_t count = 0;
};

// A tile's sides, in the order of IslandTile::skirts and of
// IslandLevels::neighbours: towards -x, +x, -z, +z.
inline constexpr int kTileSides = 4;

struct IslandTile {
    IndexRange cells; // the tile's cells at this level
    // Per side, a skirt: the level's vertices along that side, each joined to
    // a copy lowered by the side's depth (the largest distance, along that
    // side, between any level's edge and the full grid's), drawn
    // only where the neighbour across it takes another level. Empty on the
    // island's border.
    std::array<IndexRange, kTileSides> skirts{};
    // The largest vertical distance between this level's triangles over the
    // tile and the full grid's, m: exact (both are linear over each of the
    // full grid's triangles, so the distance peaks at one of its vertices).
    // Where the level's interpolated colours differ from the full grid's
    // (more than 0.02 of linear albedo at a vertex), at least the diagonal
    // of its cell: how far a colour band (the beach) may move.
    double error_m = 0.0;
};

struct IslandLevel {
    int step = 1; // the full grid's cells a cell of this level spans, each side
    std::vector<IslandTile> tiles; // row by row, as IslandLevels::boxes
    double error_m = 0.0;          // the largest of its tiles'
    std::uint32_t triangles = 0;   // its tiles' cells, skirts left out
};

struct IslandLevels {
    // The full grid's vertices (first, in its order) and the skirts'
    // lowered copies; every level's cells and skirts. The skirts' vertices
    // keep the normals and colours of the ones they hang from.
    MeshData mesh;
    std::vector<IslandLevel> levels; // finest (the full grid) first
    int tilesPerSide = 0;
    // Per tile (row by row, z then x), the box of everything any level draws
    // over it, skirts included (model space, m).
    std::vector<glm::vec3> boxLo, boxHi;
    // Per tile and side, the neighbouring tile's index, or -1 on the border.
    std::vector<std::array<int, kTileSides>> neighbours;
};

// The levels of `grid`, the heightfield makeIsland(…, resolution) built
// ((resolution + 1)^2 vertices, row by row, two triangles a cell split
// along the same diagonal). Tiles are tileCells of the full grid's cells a
// side (resolution must be a multiple of it); level k samples every 2^k-th
// vertex, down to the coarsest step that still divides tileCells. Throws
// swell::Error when the grid does not fit.
IslandLevels makeIslandLevels(const MeshData& grid, int resolution, int tileCells);

// The error's size on screen, pixels: error_m seen from distance_m by a
// projection of focal_px pixels a radian (the viewport's height times
// projection[1][1] / 2). A vertical error seen at any angle projects to at
// most this. Infinite at distance 0 (for a nonzero error).
double projectedError_px(double error_m, double distance_m, double focal_px);

// The coarsest level of tile `tile` whose error, seen from distance_m (the
// nearest point of the tile's box), projects to tolerance_px or less; level
// 0 (the full grid) when none does or the tolerance is 0.
std::size_t islandTileLevel(const IslandLevels& levels, std::size_t tile, double distance_m, double focal_px,
                            double tolerance_px);

} // namespace swell::detail
