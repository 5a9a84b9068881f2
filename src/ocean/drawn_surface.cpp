#include "swell/drawn_surface.h"

#include "ocean/drawn_search.h"
#include "swell/error.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace swell {

namespace detail {

namespace {

// Barycentric weights of p in the triangle (a, b, c) of the x,z plane;
// empty when the triangle is degenerate.
std::optional<glm::dvec3> barycentric(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b, glm::dvec2 c)
{
    const glm::dvec2 ab = b - a, ac = c - a, ap = p - a;
    const double det = ab.x * ac.y - ab.y * ac.x;
    if (std::abs(det) < 1e-18)
        return std::nullopt;
    const double v = (ap.x * ac.y - ap.y * ac.x) / det;
    const double w = (ab.x * ap.y - ab.y * ap.x) / det;
    return glm::dvec3(1.0 - v - w, v, w);
}

glm::dvec2 xz(glm::dvec3 p) { return {p.x, p.z}; }

// Whether p lies in cell (i, j): in one of its two triangles, split along
// the diagonal facing the centre, as detail::tileGrid splits them. Sets
// `missing` when a vertex could not be given.
std::optional<DrawnPoint> inCell(const GridShape& shape, int i, int j, glm::dvec2 p, const DrawnVertexFunction& vertex,
                                 bool& missing)
{
    const int half = shape.cells / 2;
    const std::optional<glm::dvec3> va = vertex(i, j), vb = vertex(i + 1, j), vc = vertex(i, j + 1),
                                    vd = vertex(i + 1, j + 1);
    if (!va || !vb || !vc || !vd) {
        missing = true;
        return std::nullopt;
    }
    const glm::dvec3 a = *va, b = *vb, c = *vc, d = *vd;
    const bool antiDiagonal = (i < half) != (j < half);
    const glm::dvec3 triangles[2][3] = {{a, c, antiDiagonal ? b : d}, {antiDiagonal ? b : a, antiDiagonal ? c : d, antiDiagonal ? d : b}};
    // The same triangles' vertices by their grid indices.
    const glm::ivec2 ia(i, j), ib(i + 1, j), ic(i, j + 1), id(i + 1, j + 1);
    const glm::ivec2 corners[2][3] = {{ia, ic, antiDiagonal ? ib : id},
                                      {antiDiagonal ? ib : ia, antiDiagonal ? ic : id, antiDiagonal ? id : ib}};
    for (int k = 0; k < 2; ++k) {
        const glm::dvec3(&t)[3] = triangles[k];
        const std::optional<glm::dvec3> w = barycentric(p, xz(t[0]), xz(t[1]), xz(t[2]));
        constexpr double kEdge = -1e-9; // a point on a shared edge belongs to either triangle
        if (!w || w->x < kEdge || w->y < kEdge || w->z < kEdge)
            continue;
        DrawnPoint out;
        out.position_m = glm::dvec3(p.x, t[0].y * w->x + t[1].y * w->y + t[2].y * w->z, p.y);
        const glm::dvec3 n = glm::cross(t[1] - t[0], t[2] - t[0]);
        out.normal = glm::normalize(n.y < 0.0 ? -n : n);
        out.cellI = i;
        out.cellJ = j;
        out.corners = {corners[k][0], corners[k][1], corners[k][2]};
        out.weights = *w;
        return out;
    }
    return std::nullopt;
}

} // namespace

glm::ivec2 restCellOf(const GridShape& shape, const GridPlacement& placement, glm::dvec2 r)
{
    const int half = shape.cells / 2;
    glm::dvec2 line; // continuous grid line index, relative to the centre
    if (shape.layout == GridLayout::Paper) {
        // s = R u |u|  =>  u = sign(s) sqrt(|s| / R).
        auto inverse = [&](double s) { return std::copysign(std::sqrt(std::abs(s) / shape.radius_m), s) * half; };
        line = {inverse(r.x), inverse(r.y)};
    } else {
        // Vertex (i, j) sits at d * f(ring) / ring with f(ring) the ring's
        // Chebyshev radius, innerScale * expm1(growth * ring / half); while
        // morphing, between that and the coarser scale's: the guess only
        // starts the search.
        const double chebyshev = std::max(std::abs(r.x), std::abs(r.y));
        if (chebyshev <= 0.0)
            return {half, half};
        auto ringOf = [&](const GridRings& rings) { return half * std::log1p(chebyshev / rings.innerScale_m) / rings.growth; };
        const double ring = glm::mix(ringOf(placement.rings), ringOf(placement.coarseRings), placement.morph);
        line = r * (ring / chebyshev);
    }
    const glm::dvec2 cell = glm::floor(line) + double(half);
    return glm::clamp(glm::ivec2(cell), glm::ivec2(0), glm::ivec2(shape.cells - 1));
}

std::optional<DrawnPoint> searchDrawnCells(const GridShape& shape, glm::ivec2 start, glm::dvec2 p, int maxRings,
                                           const DrawnVertexFunction& vertex)
{
    bool missing = false;
    for (int radius = 0; radius <= maxRings; ++radius) {
        for (int dj = -radius; dj <= radius; ++dj)
            for (int di = -radius; di <= radius; ++di) {
                if (std::max(std::abs(di), std::abs(dj)) != radius)
                    continue;
                const glm::ivec2 cell = start + glm::ivec2(di, dj);
                if (glm::any(glm::lessThan(cell, glm::ivec2(0))) || glm::any(glm::greaterThanEqual(cell, glm::ivec2(shape.cells))))
                    continue;
                if (std::optional<DrawnPoint> hit = inCell(shape, cell.x, cell.y, p, vertex, missing))
                    return hit;
                if (missing)
                    return std::nullopt;
            }
    }
    return std::nullopt;
}

} // namespace detail

DrawnSurface::DrawnSurface(std::shared_ptr<const SurfaceQuery> surface, const GridShape& shape, const HorizonFade& fade,
                           glm::dvec3 eye_m, double time_s, SeaFrame sea)
    : surface_(std::move(surface)), shape_(shape), fade_(fade), placement_(placeGrid(shape, eye_m)), eye_m_(eye_m),
      time_s_(time_s), sea_(sea)
{
    if (!surface_)
        throw Error("DrawnSurface: no surface (null)");
}

glm::dvec3 DrawnSurface::vertex(int i, int j) const
{
    // As wave_capture's CPU twin of water.vert: the rest point, the waves its
    // cell size resolves, the horizon fade at its distance from the eye, and
    // the surface sources at the rest point (shaders/water.vert).
    const GridPoint point = gridPoint(shape_, placement_, i, j);
    const glm::dvec2 rest = placement_.center_m + point.offset_m;
    const double distance_m = glm::length(rest - glm::dvec2(eye_m_.x, eye_m_.z));
    const glm::dvec3 d =
        surface_->displacementAt(rest, time_s_, SurfaceFilter{point.cellSize_m, horizonFadeAt(fade_, distance_m)});
    return sea_.toWorld(glm::dvec3(rest.x, 0.0, rest.y) + d);
}

std::optional<DrawnPoint> DrawnSurface::at(glm::dvec2 p) const
{
    // Start from the cell over the rest point the exact surface puts under p
    // (the drawn surface's differs from it by the filtered waves), then look
    // in rings of cells around it.
    const glm::dvec2 rest = surface_->restPointUnder(p, time_s_);
    const glm::ivec2 start = detail::restCellOf(shape_, placement_, rest - placement_.center_m);
    return detail::searchDrawnCells(shape_, start, p, detail::kMaxDrawnSearchRings,
                                    [this](int i, int j) { return std::optional<glm::dvec3>(vertex(i, j)); });
}

} // namespace swell
