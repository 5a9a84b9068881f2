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
    // Tiles of one cell: the far cells are long and thin, and tiles of 2 x 2
    // cells along the frustum's sides kept a fifth of the drawn triangles
    // outside the view (issue 16). Blocks of kBlockTiles x kBlockTiles tiles
    // are tested first, so the CPU tests the tiles only along the frustum's
    // edges.
    static constexpr int kTileCells = 1;
    static constexpr int kBlockTiles = 8;

    void build(const GridShape& shape);

    // Chooses the tiles to draw for a camera. viewProj maps positions relative
    // to the render origin; gridCenter_m is the grid centre relative to it.
    void cull(const GridShape& shape, const GridPlacement& placement, const WaveReach& reach,
              const glm::dmat4& viewProj, bool zeroToOneDepth, glm::dvec2 gridCenter_m);

    // Draws the chosen tiles (the grid VAO must be bound: see vertexArray()).
    // Returns the triangles submitted.
    long long draw() const;
    unsigned vertexArray() const { return vao_.id(); }

    // How many times the tiles' bounds have been computed (once per change of
    // scale, morph band or reach, not per frame).
    long long boundsComputed() const { return boundsComputed_; }

    // The indices of the chosen tiles' triangles, in the order drawn.
    std::vector<std::uint32_t> chosenIndices() const;

private:
    // Adds a range of the index buffer to the draw, merged with the last one
    // when they touch.
    void choose(std::uint32_t firstIndex, std::uint32_t indexCount);

    TiledGrid grid_;
    // Each block's and tile's bounds relative to the grid centre, for the
    // scale, morph band and reach they were computed for.
    std::vector<Bounds> blockBounds_, tileBounds_;
    bool boundsValid_ = false;
    double boundsScale_ = 0.0;
    int boundsMorphBand_ = 0;
    WaveReach boundsReach_;
    long long boundsComputed_ = 0;
    gl::Buffer indices_;
    gl::VertexArray vao_;
    // glMultiDrawElements' arguments for the chosen tiles.
    std::vector<int> counts_;
    std::vector<const void*> offsets_;
};

} // namespace swell::detail
