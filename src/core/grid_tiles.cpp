#include "core/grid_tiles.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace swell::detail {

TiledGrid tileGrid(int cells, int tileCells, int blockTiles)
{
    TiledGrid grid;
    const auto lines = std::uint32_t(cells + 1);
    const auto half = std::uint32_t(cells / 2);
    grid.indices.reserve(size_t(cells) * size_t(cells) * 6);
    const int blockCells = tileCells * blockTiles;
    for (int bj = 0; bj < cells; bj += blockCells)
        for (int bi = 0; bi < cells; bi += blockCells) {
            GridTile block{bi, std::min(bi + blockCells, cells), bj, std::min(bj + blockCells, cells),
                           std::uint32_t(grid.indices.size()), 0, int(grid.tiles.size()), 0};
            for (int j0 = block.j0; j0 < block.j1; j0 += tileCells)
                for (int i0 = block.i0; i0 < block.i1; i0 += tileCells) {
                    GridTile tile{i0, std::min(i0 + tileCells, block.i1), j0, std::min(j0 + tileCells, block.j1),
                                  std::uint32_t(grid.indices.size())};
                    for (auto j = std::uint32_t(tile.j0); j < std::uint32_t(tile.j1); ++j)
                        for (auto i = std::uint32_t(tile.i0); i < std::uint32_t(tile.i1); ++i) {
                            const std::uint32_t a = j * lines + i, b = a + 1, c = a + lines, d = c + 1;
                            if ((i < half) != (j < half))
                                grid.indices.insert(grid.indices.end(), {a, c, b, b, c, d});
                            else
                                grid.indices.insert(grid.indices.end(), {a, c, d, a, d, b});
                        }
                    tile.indexCount = std::uint32_t(grid.indices.size()) - tile.firstIndex;
                    grid.tiles.push_back(tile);
                }
            block.indexCount = std::uint32_t(grid.indices.size()) - block.firstIndex;
            block.tileCount = int(grid.tiles.size()) - block.firstTile;
            grid.blocks.push_back(block);
        }
    return grid;
}

int morphBand(double morph)
{
    return morph <= 0.0 ? 0 : std::clamp(int(std::ceil(morph * kMorphBands)), 1, kMorphBands);
}

namespace {

// Where one vertex can be, before the waves move it: a box of its unsnapped
// places, and a margin to add around it.
struct VertexExtent {
    glm::dvec2 lo{std::numeric_limits<double>::infinity()}, hi{-std::numeric_limits<double>::infinity()};
    double margin_m = 0.0;
};

// While morphing, a vertex slides in a straight line from this scale's place
// to the coarser one's: its places at both ends of the placement's morph band
// hold every place between.
class VertexExtents {
public:
    VertexExtents(const GridShape& shape, const GridPlacement& placement)
        : shape_(shape), band_(morphBand(placement.morph)), ends_{placement, placement}
    {
        ends_[0].morph = band_ == 0 ? 0.0 : double(band_ - 1) / kMorphBands;
        ends_[1].morph = double(band_) / kMorphBands;
        // The coarser grid's centre sits within 1.5 finest steps of this
        // one's (each is the camera rounded to its own step: half of one,
        // half of two), whichever way the centre snapped.
        for (GridPlacement& end : ends_)
            end.coarseCenterShift_m = glm::dvec2(0.0);
        coarseShift_m_ = ends_[1].morph * 1.5 * placement.finestStep_m;
        // gridPoint() places the geometric layout's vertex d (from the
        // centre) of ring r, inside the skirt, at d times that ring's
        // spacing before snapping, at either scale and so at any morph
        // between them (grid.cpp, geometricPoint): one point per ring gives
        // every vertex's place, and its lattice step. A rebuild then costs
        // a ring's work per ring instead of per vertex (about 5 times less).
        if (shape.layout == GridLayout::Geometric)
            for (int k = 0; k < ends(); ++k)
                for (int ring = 1; ring < shape.cells / 2; ++ring)
                    ringPoints_[size_t(k)].push_back(gridPoint(shape, ends_[k], shape.cells / 2 + ring, shape.cells / 2));
    }

    VertexExtent at(int i, int j) const
    {
        VertexExtent e;
        for (int k = 0; k < ends(); ++k) {
            const GridPoint p = pointAt(k, i, j);
            e.lo = glm::min(e.lo, p.nominal_m);
            e.hi = glm::max(e.hi, p.nominal_m);
            // Half a step of snapping, the coarser centre's shift, and the
            // GPU's float arithmetic (about 1e-6 of the distance; 1e-5 here).
            const double slack_m = 1e-5 * (std::abs(p.nominal_m.x) + std::abs(p.nominal_m.y)) + 1e-3;
            e.margin_m = std::max(e.margin_m, 0.5 * std::max(p.latticeStep_m.x, p.latticeStep_m.y) + coarseShift_m_ + slack_m);
        }
        return e;
    }

private:
    int ends() const { return band_ == 0 ? 1 : 2; }

    // gridPoint(shape_, ends_[k], i, j)'s place and lattice step.
    GridPoint pointAt(int k, int i, int j) const
    {
        const std::vector<GridPoint>& rings = ringPoints_[size_t(k)];
        const glm::ivec2 d(i - shape_.cells / 2, j - shape_.cells / 2);
        const int ring = std::max(std::abs(d.x), std::abs(d.y));
        if (ring == 0 || size_t(ring) > rings.size())
            return gridPoint(shape_, ends_[k], i, j); // the centre, the skirt, the paper's layout
        const GridPoint& onAxis = rings[size_t(ring - 1)]; // vertex (ring, 0)
        GridPoint p;
        p.nominal_m = glm::dvec2(d) * (onAxis.nominal_m.x / ring);
        p.latticeStep_m = onAxis.latticeStep_m;
        return p;
    }

    const GridShape& shape_;
    int band_;
    GridPlacement ends_[2];
    double coarseShift_m_ = 0.0;
    // Per end, rings 1 .. cells/2 - 1: gridPoint() of the ring's vertex on the +x axis.
    std::array<std::vector<GridPoint>, 2> ringPoints_;
};

// Before snapping, along a row a vertex's x grows with i, and |x| grows with
// the ring along a column (paper's layout: x depends on i alone), so the
// extremes of x lie at the tile's corners or at the point of its left or
// right edge nearest the centre; likewise for z. Eight points bound the
// tile's unsnapped places, which do not depend on where the centre snapped;
// each vertex snaps within half a lattice step of its place.
template <typename ExtentAt>
Bounds tileBounds(const GridTile& tile, int cells, const WaveReach& reach, const ExtentAt& extentAt)
{
    Bounds box{glm::dvec3(std::numeric_limits<double>::infinity()), glm::dvec3(-std::numeric_limits<double>::infinity())};
    double margin = 0.0;
    auto add = [&](int i, int j) {
        const VertexExtent e = extentAt(i, j);
        box.lo = glm::min(box.lo, glm::dvec3(e.lo.x, 0.0, e.lo.y));
        box.hi = glm::max(box.hi, glm::dvec3(e.hi.x, 0.0, e.hi.y));
        margin = std::max(margin, e.margin_m);
    };
    const int half = cells / 2;
    const int nearestI = std::clamp(half, tile.i0, tile.i1), nearestJ = std::clamp(half, tile.j0, tile.j1);
    for (const int i : {tile.i0, tile.i1})
        for (const int j : {tile.j0, tile.j1})
            add(i, j);
    add(tile.i0, nearestJ);
    add(tile.i1, nearestJ);
    add(nearestI, tile.j0);
    add(nearestI, tile.j1);
    // The snapping and float margin, then the waves' reach.
    const glm::dvec3 pad(margin + reach.horizontal_m, reach.vertical_m, margin + reach.horizontal_m);
    box.lo -= pad;
    box.hi += pad;
    return box;
}

} // namespace

Bounds tileBounds(const GridShape& shape, const GridPlacement& placement, const GridTile& tile, const WaveReach& reach)
{
    const VertexExtents extents(shape, placement);
    return tileBounds(tile, shape.cells, reach, [&](int i, int j) { return extents.at(i, j); });
}

GridBounds gridBounds(const GridShape& shape, const GridPlacement& placement, const TiledGrid& grid, const WaveReach& reach)
{
    // Each vertex's extent once (a vertex is shared by up to four tiles).
    const VertexExtents extents(shape, placement);
    const int lines = shape.cells + 1;
    std::vector<VertexExtent> table(size_t(lines) * size_t(lines));
    for (int j = 0; j < lines; ++j)
        for (int i = 0; i < lines; ++i)
            table[size_t(j) * size_t(lines) + size_t(i)] = extents.at(i, j);
    auto extentAt = [&](int i, int j) { return table[size_t(j) * size_t(lines) + size_t(i)]; };
    GridBounds out;
    out.blocks.reserve(grid.blocks.size());
    out.tiles.reserve(grid.tiles.size());
    for (const GridTile& block : grid.blocks)
        out.blocks.push_back(tileBounds(block, shape.cells, reach, extentAt));
    for (const GridTile& tile : grid.tiles)
        out.tiles.push_back(tileBounds(tile, shape.cells, reach, extentAt));
    return out;
}

Frustum frustumPlanes(const glm::dmat4& m, bool zeroToOne)
{
    const glm::dvec4 row0(m[0][0], m[1][0], m[2][0], m[3][0]);
    const glm::dvec4 row1(m[0][1], m[1][1], m[2][1], m[3][1]);
    const glm::dvec4 row2(m[0][2], m[1][2], m[2][2], m[3][2]);
    const glm::dvec4 row3(m[0][3], m[1][3], m[2][3], m[3][3]);
    return {row3 + row0, row3 - row0, row3 + row1, row3 - row1, zeroToOne ? row2 : row3 + row2, row3 - row2};
}

Containment frustumContains(const Frustum& frustum, const Bounds& box)
{
    return FrustumTest(frustum, glm::dvec3(0.0))(centred(box));
}

} // namespace swell::detail
