// The water grid on the GPU: one index buffer laid out tile by tile, and each
// frame the list of tiles that reach the view frustum, drawn with one call.
#pragma once

#include "core/grid_tiles.h"
#include "swell/gl/handle.h"

#include <glm/mat4x4.hpp>

#include <cstdint>
#include <vector>

namespace swell::detail {

class WaterGrid {
public:
    // Tiles of this many cells a side: small, so the frustum's edges waste
    // few triangles; blocks of kBlockTiles x kBlockTiles tiles are tested
    // first, so the CPU tests the small tiles only along the frustum's edges.
    static constexpr int kTileCells = 2;
    static constexpr int kBlockTiles = 4;

    void build(const GridShape& shape);

    // Chooses the tiles to draw for a camera. viewProj maps positions relative
    // to the render origin; gridCenter_m is the grid centre relative to it.
    void cull(const GridShape& shape, const GridPlacement& placement, const WaveReach& reach,
              const glm::dmat4& viewProj, glm::dvec2 gridCenter_m);

    // Draws the chosen tiles (the grid VAO must be bound: see vertexArray()).
    // Returns the triangles submitted.
    long long draw() const;
    unsigned vertexArray() const { return vao_.id(); }

    // The indices of the chosen tiles' triangles, in the order drawn.
    std::vector<std::uint32_t> chosenIndices() const;

private:
    // Adds a range of the index buffer to the draw, merged with the last one
    // when they touch.
    void choose(std::uint32_t firstIndex, std::uint32_t indexCount);

    TiledGrid grid_;
    // Each block's and tile's bounds relative to the grid centre, for the
    // placement and reach they were computed for.
    std::vector<Bounds> blockBounds_, tileBounds_;
    bool boundsValid_ = false;
    glm::dvec2 boundsCenter_m_{0.0};
    double boundsScale_ = 0.0;
    WaveReach boundsReach_;
    gl::Buffer indices_;
    gl::VertexArray vao_;
    // glMultiDrawElements' arguments for the chosen tiles.
    std::vector<int> counts_;
    std::vector<const void*> offsets_;
};

} // namespace swell::detail
