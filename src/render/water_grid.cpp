#include "render/water_grid.h"

#include <epoxy/gl.h>

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
    // morph band, or the surface's reach changes. A camera that moves,
    // turns, or climbs within a band reuses them.
    const int morphing = morphBand(placement.morph);
    if (!boundsValid_ || placement.scale != boundsScale_ || morphing != boundsMorphBand_ ||
        reach.vertical_m != boundsReach_.vertical_m || reach.horizontal_m != boundsReach_.horizontal_m) {
        GridBounds bounds = gridBounds(shape, placement, grid_, reach);
        blockBounds_ = std::move(bounds.blocks);
        tileBounds_ = std::move(bounds.tiles);
        boundsValid_ = true;
        boundsScale_ = placement.scale;
        boundsMorphBand_ = morphing;
        boundsReach_ = reach;
        ++boundsComputed_;
    }
    const Frustum frustum = frustumPlanes(viewProj, zeroToOneDepth);
    const glm::dvec3 centre(gridCenter_m.x, 0.0, gridCenter_m.y);
    counts_.clear();
    offsets_.clear();
    auto moved = [&](Bounds box) {
        box.lo += centre;
        box.hi += centre;
        return box;
    };
    for (size_t b = 0; b < grid_.blocks.size(); ++b) {
        const GridTile& block = grid_.blocks[b];
        const Containment c = frustumContains(frustum, moved(blockBounds_[b]));
        if (c == Containment::Outside)
            continue;
        if (c == Containment::Inside) {
            choose(block.firstIndex, block.indexCount);
            continue;
        }
        for (int t = block.firstTile; t < block.firstTile + block.tileCount; ++t) {
            const GridTile& tile = grid_.tiles[size_t(t)];
            if (frustumContains(frustum, moved(tileBounds_[size_t(t)])) != Containment::Outside)
                choose(tile.firstIndex, tile.indexCount);
        }
    }
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
