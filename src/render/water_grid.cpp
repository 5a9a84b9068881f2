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
}

void WaterGrid::cull(const GridShape& shape, const GridPlacement& placement, const WaveReach& reach,
                     const glm::dmat4& viewProj, glm::dvec2 gridCenter_m)
{
    const Frustum frustum = frustumPlanes(viewProj);
    const glm::dvec3 centre(gridCenter_m.x, 0.0, gridCenter_m.y);
    counts_.clear();
    offsets_.clear();
    auto bounds = [&](const GridTile& t) {
        Bounds box = tileBounds(shape, placement, t, reach);
        box.lo += centre;
        box.hi += centre;
        return box;
    };
    for (const GridTile& block : grid_.blocks) {
        const Containment c = frustumContains(frustum, bounds(block));
        if (c == Containment::Outside)
            continue;
        if (c == Containment::Inside) {
            choose(block.firstIndex, block.indexCount);
            continue;
        }
        for (int t = block.firstTile; t < block.firstTile + block.tileCount; ++t) {
            const GridTile& tile = grid_.tiles[size_t(t)];
            if (frustumContains(frustum, bounds(tile)) != Containment::Outside)
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
