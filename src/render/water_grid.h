// The water grid on the GPU: one index buffer laid out tile by tile, and each
// frame the list of tiles that reach the view frustum, drawn with one call.
#pragma once

#include "core/grid_tiles.h"
#include "swell/gl/handle.h"

#include <glm/mat4x4.hpp>

#include <cstddef>
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
    static constexpr int kBlockTiles = 8; // at most 8: a block's tiles are bits of a 64-bit mask

    void build(const GridShape& shape);

    // Chooses the tiles to draw for a camera. viewProj maps positions relative
    // to the render origin; gridCenter_m is the grid centre relative to it.
    void cull(const GridShape& shape, const GridPlacement& placement, const WaveReach& reach,
              const glm::dmat4& viewProj, bool zeroToOneDepth, glm::dvec2 gridCenter_m);

    // Draws the chosen tiles (the grid VAO must be bound: see vertexArray()).
    // Returns the triangles submitted.
    long long draw() const;
    // Draws the chosen tiles a range of the index buffer at a time, telling
    // `beforeRange` each range's first triangle (its index in the buffer
    // over 3) first: gl_PrimitiveID counts from each draw's start, and the
    // water's visibility pass writes the triangle's place in the buffer
    // (render/water_visibility.h). Returns the triangles submitted.
    template <class BeforeRange>
    long long drawRanges(BeforeRange beforeRange) const
    {
        long long triangles = 0;
        for (std::size_t k = 0; k < counts_.size(); ++k) {
            beforeRange(std::uint32_t(reinterpret_cast<std::uintptr_t>(offsets_[k]) / (3 * sizeof(std::uint32_t))));
            glDrawElements(GL_TRIANGLES, counts_[k], GL_UNSIGNED_INT, offsets_[k]);
            triangles += counts_[k] / 3;
        }
        return triangles;
    }
    // The draws drawRanges() makes: one a range of the chosen tiles.
    int rangeCount() const { return int(counts_.size()); }
    unsigned vertexArray() const { return vao_.id(); }
    // The index buffer: triangle t is indices 3t to 3t + 2.
    unsigned indexBuffer() const { return indices_.id(); }

    // How many times the tiles' bounds have been computed (once per change of
    // scale, morph band or reach, not per frame).
    long long boundsComputed() const { return boundsComputed_; }
    // How many boxes the last cull() tested against the frustum.
    int boxesTested() const { return boxesTested_; }

    // The indices of the chosen tiles' triangles, in the order drawn.
    std::vector<std::uint32_t> chosenIndices() const;

private:
    // Adds a range of the index buffer to the draw, merged with the last one
    // when they touch.
    void choose(std::uint32_t firstIndex, std::uint32_t indexCount);
    // Each block's quadtree nodes' boxes from its tiles' (see nodes_).
    void computeNodeBoxes(const std::vector<Bounds>& tiles);
    // Marks in `mask` (bit ty * kBlockTiles + tx) the tiles of block b's node
    // (level, nx, ny) that reach the frustum (level kNodeLevels: the tile
    // at nx, ny), tested in the grid centre's frame.
    // planes: those the block or node above left to test (FrustumTest).
    void chooseTiles(const FrustumTest& test, unsigned planes, size_t b, int level, int nx, int ny, std::uint64_t& mask);
    // A block's tiles in a row and in a column.
    static int tilesAcross(const GridTile& block);
    static int tilesDown(const GridTile& block);

    TiledGrid grid_;
    // Each block's and tile's box relative to the grid centre, for the scale
    // and morph band they were computed for, without the waves' reach.
    std::vector<CentredBox> blockBoxes_, tileBoxes_;
    // A partly visible block is split as a quadtree down to its tiles: level
    // k's nodes are kBlockTiles >> (k + 1) tiles on a side, (2^(k+1))^2 of
    // them a block, each node's box the union of its tiles' (empty past a
    // block's edge). A node outside the frustum rules out every tile in it,
    // one inside takes them all: the tiles chosen are those a test of each
    // tile alone would choose, for about a third of the tests.
    static constexpr int kNodeLevels = 2;
    struct Node {
        CentredBox box;
        bool empty = true;
    };
    std::vector<Node> nodes_[kNodeLevels];
    static_assert(kBlockTiles == 2 << kNodeLevels, "the quadtree's last level is the tiles");
    bool boundsValid_ = false;
    double boundsScale_ = 0.0;
    int boundsMorphBand_ = 0;
    long long boundsComputed_ = 0;
    int boxesTested_ = 0;
    gl::Buffer indices_;
    gl::VertexArray vao_;
    // glMultiDrawElements' arguments for the chosen tiles.
    std::vector<int> counts_;
    std::vector<const void*> offsets_;
};

} // namespace swell::detail
