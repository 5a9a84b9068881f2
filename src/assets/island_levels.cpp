// The island's levels of detail: tiles at coarser grids over the full
// grid's vertices, their exact errors, the skirts between them, and the
// choice of a tile's level.
#include "assets/island_levels.h"

#include "swell/error.h"

#include <fmt/format.h>
#include <glm/common.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace swell::detail {

namespace {

// Below the deepest gap a skirt must hide, m: float rounding of the heights.
constexpr double kSkirtMargin_m = 0.01;
// A level whose interpolated colour differs from the full grid's by more
// than this (linear albedo, any channel) at one of its vertices moves a
// colour band (the beach's, 3.5 m of height wide): see makeIslandLevels.
constexpr float kColorTolerance = 0.02f;

struct Grid {
    const MeshData& mesh;
    int n;
    std::uint32_t index(int i, int j) const { return std::uint32_t(j * (n + 1) + i); }
    double height(int i, int j) const { return double(mesh.vertices[index(i, j)].position.y); }
};

// The level of `step` at the full grid's vertex (i, j), as drawn: inside
// the coarse cell that holds it, on the same one of the cell's two
// triangles the index buffer draws ({a, c, b} and {b, c, d}, split along
// the diagonal from (i0 + step, j0) to (i0, j0 + step)), its height and its
// colour interpolated from that triangle's corners.
struct Drawn {
    double height_m;
    glm::vec3 color;
};

Drawn coarseAt(const Grid& g, int step, int i, int j)
{
    const int i0 = std::min(i / step * step, g.n - step), j0 = std::min(j / step * step, g.n - step);
    const double u = double(i - i0) / step, v = double(j - j0) / step;
    const std::uint32_t a = g.index(i0, j0), b = g.index(i0 + step, j0), c = g.index(i0, j0 + step),
                        d = g.index(i0 + step, j0 + step);
    // The corner the weights start from and the two it leans towards.
    const bool first = u + v <= 1.0;
    const std::uint32_t o = first ? a : d, x = first ? b : c, z = first ? c : b;
    const double wx = first ? u : 1.0 - u, wz = first ? v : 1.0 - v;
    const MeshVertex &vo = g.mesh.vertices[o], &vx = g.mesh.vertices[x], &vz = g.mesh.vertices[z];
    return {vo.position.y + wx * (vx.position.y - vo.position.y) + wz * (vz.position.y - vo.position.y),
            vo.color + float(wx) * (vx.color - vo.color) + float(wz) * (vz.color - vo.color)};
}

// The grid point m steps along side `side` of the tile whose lowest corner is (i0, j0).
glm::ivec2 sidePoint(int side, int i0, int j0, int cells, int m)
{
    switch (side) {
    case 0: return {i0, j0 + m};
    case 1: return {i0 + cells, j0 + m};
    case 2: return {i0 + m, j0};
    default: return {i0 + m, j0 + cells};
    }
}

} // namespace

IslandLevels makeIslandLevels(const MeshData& grid, int resolution, int tileCells)
{
    const int n = resolution;
    if (n <= 0 || tileCells <= 0 || n % tileCells != 0 || grid.vertices.size() != std::size_t(n + 1) * std::size_t(n + 1))
        throw Error(fmt::format("makeIslandLevels: a {}-cell grid of {} vertices cannot be cut into tiles of {} cells",
                                n, grid.vertices.size(), tileCells));
    const Grid g{grid, n};
    IslandLevels out;
    out.mesh.vertices = grid.vertices;
    std::vector<MeshVertex>& vertices = out.mesh.vertices;
    std::vector<std::uint32_t>& indices = out.mesh.indices;
    const int tiles = n / tileCells;
    out.tilesPerSide = tiles;
    const double cell_m = double(grid.vertices[1].position.x - grid.vertices[0].position.x);
    std::vector<int> steps;
    for (int step = 1; tileCells % step == 0; step *= 2)
        steps.push_back(step);

    // Each side's depth: the largest distance along it between any level's
    // edge (linear between that level's vertices, as its cells are there)
    // and the full grid's. Two tiles sharing a side compute the same value,
    // so their skirts both reach below the gap whichever edge lies higher.
    std::vector<std::array<double, kTileSides>> depth(std::size_t(tiles * tiles));
    for (int tj = 0; tj < tiles; ++tj)
        for (int ti = 0; ti < tiles; ++ti) {
            const std::size_t t = std::size_t(tj * tiles + ti);
            std::array<int, kTileSides>& nb = out.neighbours.emplace_back();
            nb = {ti > 0 ? int(t) - 1 : -1, ti + 1 < tiles ? int(t) + 1 : -1, tj > 0 ? int(t) - tiles : -1,
                  tj + 1 < tiles ? int(t) + tiles : -1};
            glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
            for (int j = tj * tileCells; j <= (tj + 1) * tileCells; ++j)
                for (int i = ti * tileCells; i <= (ti + 1) * tileCells; ++i) {
                    lo = glm::min(lo, grid.vertices[g.index(i, j)].position);
                    hi = glm::max(hi, grid.vertices[g.index(i, j)].position);
                }
            double deepest = 0.0;
            for (int side = 0; side < kTileSides; ++side) {
                double d = 0.0;
                for (const int step : steps)
                    for (int m = 0; m <= tileCells; ++m) {
                        const int m0 = std::min(m / step * step, tileCells - step);
                        const glm::ivec2 p = sidePoint(side, ti * tileCells, tj * tileCells, tileCells, m);
                        const glm::ivec2 a = sidePoint(side, ti * tileCells, tj * tileCells, tileCells, m0);
                        const glm::ivec2 b = sidePoint(side, ti * tileCells, tj * tileCells, tileCells, m0 + step);
                        const double f = double(m - m0) / step;
                        const double line = g.height(a.x, a.y) + f * (g.height(b.x, b.y) - g.height(a.x, a.y));
                        d = std::max(d, std::abs(g.height(p.x, p.y) - line));
                    }
                depth[t][std::size_t(side)] = d + kSkirtMargin_m;
                deepest = std::max(deepest, depth[t][std::size_t(side)]);
            }
            lo.y -= float(deepest);
            out.boxLo.push_back(lo);
            out.boxHi.push_back(hi);
        }

    for (const int step : steps) {
        IslandLevel& level = out.levels.emplace_back();
        level.step = step;
        for (int tj = 0; tj < tiles; ++tj)
            for (int ti = 0; ti < tiles; ++ti) {
                const std::size_t t = std::size_t(tj * tiles + ti);
                const int i0 = ti * tileCells, j0 = tj * tileCells;
                IslandTile& tile = level.tiles.emplace_back();
                // The vertical error, and where the level's colours differ
                // from the full grid's, the horizontal reach of its cell's
                // diagonal: a colour band (the beach) drawn up to that far
                // from where it lies.
                bool colorMoved = false;
                for (int j = j0; j <= j0 + tileCells; ++j)
                    for (int i = i0; i <= i0 + tileCells; ++i) {
                        const Drawn drawn = coarseAt(g, step, i, j);
                        tile.error_m = std::max(tile.error_m, std::abs(g.height(i, j) - drawn.height_m));
                        const glm::vec3 off = glm::abs(drawn.color - grid.vertices[g.index(i, j)].color);
                        colorMoved = colorMoved || std::max({off.x, off.y, off.z}) > kColorTolerance;
                    }
                if (colorMoved)
                    tile.error_m = std::max(tile.error_m, std::sqrt(2.0) * step * cell_m);
                level.error_m = std::max(level.error_m, tile.error_m);
                tile.cells.first = std::uint32_t(indices.size());
                for (int j = j0; j < j0 + tileCells; j += step)
                    for (int i = i0; i < i0 + tileCells; i += step) {
                        const std::uint32_t a = g.index(i, j), b = g.index(i + step, j), c = g.index(i, j + step),
                                            d = g.index(i + step, j + step);
                        indices.insert(indices.end(), {a, c, b, b, c, d});
                    }
                tile.cells.count = std::uint32_t(indices.size()) - tile.cells.first;
                level.triangles += tile.cells.count / 3;
                for (int side = 0; side < kTileSides; ++side) {
                    if (out.neighbours[t][std::size_t(side)] < 0)
                        continue;
                    IndexRange& skirt = tile.skirts[std::size_t(side)];
                    skirt.first = std::uint32_t(indices.size());
                    std::uint32_t upperPrev = 0, lowerPrev = 0;
                    for (int m = 0; m <= tileCells; m += step) {
                        const glm::ivec2 p = sidePoint(side, i0, j0, tileCells, m);
                        const std::uint32_t upper = g.index(p.x, p.y), lower = std::uint32_t(vertices.size());
                        MeshVertex hanging = grid.vertices[upper];
                        hanging.position.y -= float(depth[t][std::size_t(side)]);
                        vertices.push_back(hanging);
                        if (m > 0)
                            indices.insert(indices.end(), {upperPrev, upper, lowerPrev, upper, lower, lowerPrev});
                        upperPrev = upper;
                        lowerPrev = lower;
                    }
                    skirt.count = std::uint32_t(indices.size()) - skirt.first;
                }
            }
    }
    return out;
}

double projectedError_px(double error_m, double distance_m, double focal_px)
{
    if (distance_m <= 0.0)
        return error_m > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
    return error_m * focal_px / distance_m;
}

std::size_t islandTileLevel(const IslandLevels& levels, std::size_t tile, double distance_m, double focal_px,
                            double tolerance_px)
{
    std::size_t chosen = 0;
    if (tolerance_px <= 0.0)
        return chosen;
    for (std::size_t k = 1; k < levels.levels.size(); ++k)
        if (projectedError_px(levels.levels[k].tiles[tile].error_m, distance_m, focal_px) <= tolerance_px)
            chosen = k;
    return chosen;
}

} // namespace swell::detail
