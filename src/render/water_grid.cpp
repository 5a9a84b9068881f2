#include "render/water_grid.h"

#include <epoxy/gl.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <bit>

namespace swell::detail {

void WaterGrid::build(const GridShape& shape)
{
    grid_ = tileGrid(shape.cells, kTileCells, kBlockTiles);
    indices_ = gl::Buffer::create();
    glNamedBufferStorage(indices_.id(), GLsizeiptr(grid_.indices.size() * sizeof(std::uint32_t)), grid_.indices.data(), 0);
    vao_ = gl::VertexArray::create();
    glVertexArrayElementBuffer(vao_.id(), indices_.id());
    counts_.clear();
    offsets_.clear();
    boundsValid_ = false;
}

void WaterGrid::cull(const GridShape& shape, const GridPlacement& placement, const WaveReach& reach,
                     const glm::dmat4& viewProj, bool zeroToOneDepth, glm::dvec2 gridCenter_m)
{
    // The bounds, relative to the grid centre, hold wherever the centre
    // snaps (tileBounds()): they change only when the grid changes scale or
    // morph band. A camera that moves, turns, or climbs within a band reuses
    // them; the waves' reach, which may change every frame, pads them as
    // they are tested.
    const int morphing = morphBand(placement.morph);
    if (!boundsValid_ || placement.scale != boundsScale_ || morphing != boundsMorphBand_) {
        GridBounds bounds = gridBounds(shape, placement, grid_, WaveReach{});
        blockBoxes_.clear();
        tileBoxes_.clear();
        for (const Bounds& b : bounds.blocks)
            blockBoxes_.push_back(centred(b));
        for (const Bounds& t : bounds.tiles)
            tileBoxes_.push_back(centred(t));
        computeNodeBoxes(bounds.tiles);
        boundsValid_ = true;
        boundsScale_ = placement.scale;
        boundsMorphBand_ = morphing;
        ++boundsComputed_;
    }
    // The planes moved to the grid centre's frame, where the boxes are:
    // n . (p + c) + w = n . p + (n . c + w).
    Frustum frustum = frustumPlanes(viewProj, zeroToOneDepth);
    const glm::dvec3 centre(gridCenter_m.x, 0.0, gridCenter_m.y);
    for (glm::dvec4& plane : frustum)
        plane.w += glm::dot(glm::dvec3(plane), centre);
    const FrustumTest test(frustum, glm::dvec3(reach.horizontal_m, reach.vertical_m, reach.horizontal_m));
    counts_.clear();
    offsets_.clear();
    boxesTested_ = 0;
    for (size_t b = 0; b < grid_.blocks.size(); ++b) {
        const GridTile& block = grid_.blocks[b];
        ++boxesTested_;
        unsigned planes = FrustumTest::kAllPlanes;
        const Containment c = test(blockBoxes_[b], planes);
        if (c == Containment::Outside)
            continue;
        if (c == Containment::Inside) {
            choose(block.firstIndex, block.indexCount);
            continue;
        }
        std::uint64_t mask = 0;
        for (int ny = 0; ny < 2; ++ny)
            for (int nx = 0; nx < 2; ++nx)
                chooseTiles(test, planes, b, 0, nx, ny, mask);
        // In the buffer's order (row by row), a run of chosen tiles at a
        // time: a block's tiles lie one after another in the buffer, a row
        // after the row before, so consecutive bits (bits past a narrow
        // block's width are never set) are one range of indices, which
        // choose() would have merged tile by tile.
        const int width = tilesAcross(block);
        while (mask != 0) {
            const int bit = std::countr_zero(mask);
            const int run = std::countr_one(mask >> bit);
            mask = bit + run == 64 ? 0 : mask & ~(((std::uint64_t(1) << run) - 1) << bit);
            const int first = block.firstTile + (bit / kBlockTiles) * width + bit % kBlockTiles;
            const GridTile& head = grid_.tiles[size_t(first)];
            const GridTile& tail = grid_.tiles[size_t(first + run - 1)];
            choose(head.firstIndex, tail.firstIndex + tail.indexCount - head.firstIndex);
        }
    }
}

int WaterGrid::tilesAcross(const GridTile& block) { return (block.i1 - block.i0 + kTileCells - 1) / kTileCells; }
int WaterGrid::tilesDown(const GridTile& block) { return (block.j1 - block.j0 + kTileCells - 1) / kTileCells; }

void WaterGrid::computeNodeBoxes(const std::vector<Bounds>& tiles)
{
    for (int level = 0; level < kNodeLevels; ++level) {
        const int perSide = 2 << level, side = kBlockTiles / perSide;
        std::vector<Bounds> boxes(grid_.blocks.size() * size_t(perSide * perSide));
        std::vector<bool> empty(boxes.size(), true);
        for (size_t b = 0; b < grid_.blocks.size(); ++b) {
            const GridTile& block = grid_.blocks[b];
            const int width = tilesAcross(block), height = tilesDown(block);
            for (int ty = 0; ty < height; ++ty)
                for (int tx = 0; tx < width; ++tx) {
                    const Bounds& tile = tiles[size_t(block.firstTile + ty * width + tx)];
                    const size_t n = b * size_t(perSide * perSide) + size_t((ty / side) * perSide + tx / side);
                    boxes[n].lo = empty[n] ? tile.lo : glm::min(boxes[n].lo, tile.lo);
                    boxes[n].hi = empty[n] ? tile.hi : glm::max(boxes[n].hi, tile.hi);
                    empty[n] = false;
                }
        }
        nodes_[size_t(level)].clear();
        for (size_t n = 0; n < boxes.size(); ++n)
            nodes_[size_t(level)].push_back({centred(boxes[n]), empty[n]});
    }
}

void WaterGrid::chooseTiles(const FrustumTest& test, unsigned planes, size_t b, int level, int nx, int ny,
                            std::uint64_t& mask)
{
    const GridTile& block = grid_.blocks[b];
    const int width = tilesAcross(block), height = tilesDown(block);
    if (level == kNodeLevels) {
        // A single tile.
        if (nx >= width || ny >= height)
            return;
        ++boxesTested_;
        if (test(tileBoxes_[size_t(block.firstTile + ny * width + nx)], planes) != Containment::Outside)
            mask |= std::uint64_t(1) << (ny * kBlockTiles + nx);
        return;
    }
    const int perSide = 2 << level, side = kBlockTiles / perSide; // nodes across a block; tiles across a node
    const Node& node = nodes_[size_t(level)][b * size_t(perSide * perSide) + size_t(ny * perSide + nx)];
    if (node.empty)
        return;
    ++boxesTested_;
    const Containment c = test(node.box, planes);
    if (c == Containment::Outside)
        return;
    // A node whose box is mostly the waves' reach (its tiles far smaller
    // than the reach around them, as near the camera in a storm): its
    // tiles' boxes are nearly its own, and testing each of them would rule
    // out hardly any triangle. It is drawn whole.
    const bool padded = 4.0 * std::max(node.box.half.x, node.box.half.z) < test.horizontalPad_m();
    if (c == Containment::Inside || padded) {
        for (int ty = ny * side; ty < std::min((ny + 1) * side, height); ++ty)
            for (int tx = nx * side; tx < std::min((nx + 1) * side, width); ++tx)
                mask |= std::uint64_t(1) << (ty * kBlockTiles + tx);
        return;
    }
    for (int cy = 0; cy < 2; ++cy)
        for (int cx = 0; cx < 2; ++cx)
            chooseTiles(test, planes, b, level + 1, 2 * nx + cx, 2 * ny + cy, mask);
}

void WaterGrid::choose(std::uint32_t firstIndex, std::uint32_t indexCount)
{
    const auto offset = reinterpret_cast<const void*>(std::uintptr_t(firstIndex) * sizeof(std::uint32_t));
    // Neighbouring tiles are neighbours in the buffer too: merge their ranges.
    if (!counts_.empty() &&
        reinterpret_cast<std::uintptr_t>(offsets_.back()) + std::uintptr_t(counts_.back()) * sizeof(std::uint32_t) ==
            reinterpret_cast<std::uintptr_t>(offset)) {
        counts_.back() += int(indexCount);
        return;
    }
    counts_.push_back(int(indexCount));
    offsets_.push_back(offset);
}

long long WaterGrid::draw() const
{
    if (counts_.empty())
        return 0;
    glMultiDrawElements(GL_TRIANGLES, counts_.data(), GL_UNSIGNED_INT, offsets_.data(), GLsizei(counts_.size()));
    long long indices = 0;
    for (int c : counts_)
        indices += c;
    return indices / 3;
}

std::vector<std::uint32_t> WaterGrid::chosenIndices() const
{
    std::vector<std::uint32_t> out;
    for (size_t k = 0; k < counts_.size(); ++k) {
        const auto first = reinterpret_cast<std::uintptr_t>(offsets_[k]) / sizeof(std::uint32_t);
        out.insert(out.end(), grid_.indices.begin() + std::ptrdiff_t(first),
                   grid_.indices.begin() + std::ptrdiff_t(first + size_t(counts_[k])));
    }
    return out;
}

} // namespace swell::detail
