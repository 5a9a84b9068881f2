// The water grid cut into square tiles of cells, so the tiles outside the view
// frustum can be left out of the draw. Tile bounds hold the displaced surface
// wherever the waves move it; the test against the frustum is conservative:
// a tile is culled only when all of its bounds lie outside one frustum plane.
#pragma once

#include "swell/scene/grid.h"
#include "swell/scene/waves.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <vector>

namespace swell::detail {

// Cells [i0, i1) x [j0, j1) and where their triangles sit in the index
// buffer; for a block, also which tiles it holds.
struct GridTile {
    int i0 = 0, i1 = 0, j0 = 0, j1 = 0;
    std::uint32_t firstIndex = 0, indexCount = 0;
    int firstTile = 0, tileCount = 0;
};

// Tiles of up to tileCells x tileCells cells covering a grid of cells x cells,
// grouped in blocks of up to blockTiles x blockTiles tiles, so culling can
// test a block first and its tiles only when the frustum's edge crosses it.
// The triangle indices are laid out block by block and, within a block, tile
// by tile, so a block's tiles are one range. Each cell is split along the
// diagonal facing the centre, so the four quadrants mirror each other.
struct TiledGrid {
    std::vector<GridTile> blocks;
    std::vector<GridTile> tiles;
    std::vector<std::uint32_t> indices;
};
TiledGrid tileGrid(int cells, int tileCells, int blockTiles);

struct Bounds {
    glm::dvec3 lo{0.0}, hi{0.0};
};
// The morph toward the coarser scale in kMorphBands bands: 0 while not
// morphing, else 1 + the band (of width 1 / kMorphBands) holding morph.
// Bounds hold for a whole band, so they change kMorphBands times a climb
// through a scale's morph, not every frame; 16 keeps them within 1/16 of
// the slide of their tight size.
constexpr int kMorphBands = 16;
int morphBand(double morph);

// A box holding every displaced vertex of the tile, relative to the grid
// centre, wherever the centre snapped at placement's scale, and for every
// morph in placement's morph band (so it holds until the scale or the band
// changes). Its margin covers the snapping (half a lattice step), the GPU's
// float arithmetic and the waves' reach.
Bounds tileBounds(const GridShape& shape, const GridPlacement& placement, const GridTile& tile, const WaveReach& reach);
// tileBounds() of every block and tile of `grid`, finding each vertex's
// places once.
struct GridBounds {
    std::vector<Bounds> blocks, tiles;
};
GridBounds gridBounds(const GridShape& shape, const GridPlacement& placement, const TiledGrid& grid, const WaveReach& reach);

// The six planes (a, b, c, d) of a view-projection's clip volume: a point p is
// inside when dot(plane, (p, 1)) >= 0 for all six: clip z in -w..w (GL's
// default), or in 0..w when zeroToOne (glClipControl's GL_ZERO_TO_ONE, the
// convention of reversed-Z; an infinite far plane leaves that plane empty).
// A box is Outside when it lies wholly outside one plane (conservative: a box
// past a corner of the frustum may count as Partly), Inside when wholly inside all.
using Frustum = std::array<glm::dvec4, 6>;
Frustum frustumPlanes(const glm::dmat4& viewProj, bool zeroToOne = false);
enum class Containment { Outside, Partly, Inside };
Containment frustumContains(const Frustum& frustum, const Bounds& box);

// A box as its centre and half its size.
struct CentredBox {
    glm::dvec3 centre{0.0}, half{0.0};
};
inline CentredBox centred(const Bounds& box) { return {0.5 * (box.lo + box.hi), 0.5 * (box.hi - box.lo)}; }

// frustumContains() for the many boxes of one cull, each grown by the same
// pad (the waves' reach, which changes from frame to frame while the boxes
// do not). Along a plane's normal n a box spans n . centre +- |n| . half:
// no corner is chosen by the normal's signs (branches the CPU mispredicts
// from box to box), and the pad's part, |n| . pad, is found once a plane.
class FrustumTest {
public:
    FrustumTest(const Frustum& frustum, glm::dvec3 pad) : horizontalPad_m_(std::max(pad.x, pad.z))
    {
        for (size_t k = 0; k < frustum.size(); ++k) {
            planes_[k] = frustum[k];
            absNormals_[k] = glm::abs(glm::dvec3(frustum[k]));
            padRadius_[k] = glm::dot(absNormals_[k], pad);
        }
    }
    Containment operator()(const CentredBox& box) const
    {
        unsigned planes = kAllPlanes;
        return (*this)(box, planes);
    }
    // The same, testing only the planes whose bits are set in `planes`
    // (bit k: plane k), and clearing the bits of those the box lies wholly
    // inside: a box within this one lies inside them too, so testing its
    // children with what is left gives what testing every plane would.
    static constexpr unsigned kAllPlanes = 0x3f;
    Containment operator()(const CentredBox& box, unsigned& planes) const
    {
        for (unsigned left = planes; left != 0; left &= left - 1) {
            const auto k = size_t(std::countr_zero(left));
            const double distance = glm::dot(glm::dvec3(planes_[k]), box.centre) + planes_[k].w;
            const double radius = glm::dot(absNormals_[k], box.half) + padRadius_[k];
            if (distance + radius < 0.0)
                return Containment::Outside;
            if (distance - radius >= 0.0)
                planes &= ~(1u << k);
        }
        return planes == 0 ? Containment::Inside : Containment::Partly;
    }

    // The pad's larger horizontal half.
    double horizontalPad_m() const { return horizontalPad_m_; }

private:
    double horizontalPad_m_;
    Frustum planes_{};
    std::array<glm::dvec3, 6> absNormals_{};
    std::array<double, 6> padRadius_{};
};

} // namespace swell::detail
