// The drawn seabed (seabed_mesh.h): each shape a grid of vertices in its
// own frame, with rows where its profile bends so that its planes are drawn
// exactly, heights from the shape's own function.
#include "assets/seabed_mesh.h"

#include "assets/seabed_data.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

namespace swell::detail {

namespace {

// Colours as the island's (assets/mesh_data.cpp makeIsland): sand wet
// below 1 m under the sea's level, dry above; rubble grey.
glm::vec3 sandColor(double height_m) { return height_m < -1.0 ? glm::vec3(0.55f, 0.50f, 0.38f) : glm::vec3(0.80f, 0.73f, 0.55f); }
glm::vec3 rockColor(double) { return {0.42f, 0.40f, 0.37f}; }

// Where a sheet's vertex lies: its world [x, z] and height, m.
struct SheetPoint {
    glm::dvec2 world_m;
    double height_m;
};

// A grid sheet: vertex (i, j) at point(us[i], vs[j]). Its triangles face up;
// with `wallBottom_m`, vertical walls run from its four edges down to that
// height, facing out.
struct Sheet {
    std::vector<double> us, vs;
    std::function<SheetPoint(double u, double v)> point;
    glm::vec3 (*color)(double height_m) = sandColor;
    std::optional<double> wallBottom_m;
};

class MeshBuilder {
public:
    explicit MeshBuilder(glm::dvec2 origin_m) : origin_m_(origin_m) {}

    void add(const Sheet& sheet)
    {
        const auto base = std::uint32_t(mesh_.vertices.size());
        const std::size_t nu = sheet.us.size(), nv = sheet.vs.size();
        glm::dvec3 centre(0.0);
        for (double v : sheet.vs)
            for (double u : sheet.us) {
                const SheetPoint p = sheet.point(u, v);
                centre += vertex(p, sheet.color(p.height_m)) / double(nu * nv);
            }
        const auto at = [&](std::size_t i, std::size_t j) { return base + std::uint32_t(j * nu + i); };
        for (std::size_t j = 0; j + 1 < nv; ++j)
            for (std::size_t i = 0; i + 1 < nu; ++i) {
                triangle(at(i, j), at(i + 1, j), at(i, j + 1), glm::dvec3(0.0, 1.0, 0.0));
                triangle(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1), glm::dvec3(0.0, 1.0, 0.0));
            }
        if (!sheet.wallBottom_m)
            return;
        // The edges, each as the indices of its vertices in order.
        std::vector<std::vector<std::uint32_t>> edges(4);
        for (std::size_t i = 0; i < nu; ++i) {
            edges[0].push_back(at(i, 0));
            edges[1].push_back(at(i, nv - 1));
        }
        for (std::size_t j = 0; j < nv; ++j) {
            edges[2].push_back(at(0, j));
            edges[3].push_back(at(nu - 1, j));
        }
        for (const auto& edge : edges)
            wall(edge, *sheet.wallBottom_m, centre);
    }

    SeabedMesh finish()
    {
        addTriangleNormals(mesh_);
        return {std::move(mesh_), origin_m_};
    }

private:
    glm::dvec3 vertex(const SheetPoint& p, glm::vec3 color)
    {
        const glm::dvec3 position(p.world_m.x - origin_m_.x, p.height_m, p.world_m.y - origin_m_.y);
        mesh_.vertices.push_back({glm::vec3(position), {}, color});
        return position;
    }

    // A triangle wound so that its normal (addTriangleNormals) has a positive
    // part along `facing`.
    void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c, glm::dvec3 facing)
    {
        const glm::dvec3 pa(mesh_.vertices[a].position), pb(mesh_.vertices[b].position), pc(mesh_.vertices[c].position);
        if (glm::dot(glm::cross(pb - pa, pc - pa), facing) < 0.0)
            std::swap(b, c);
        mesh_.indices.insert(mesh_.indices.end(), {a, b, c});
    }

    // A wall from the vertices `edge` (copied, so its normals are its own)
    // down to bottom_m, facing away from `centre`.
    void wall(const std::vector<std::uint32_t>& edge, double bottom_m, glm::dvec3 centre)
    {
        const auto base = std::uint32_t(mesh_.vertices.size());
        for (std::uint32_t e : edge) {
            const MeshVertex top = mesh_.vertices[e];
            mesh_.vertices.push_back(top);
            mesh_.vertices.push_back({{top.position.x, float(std::min(bottom_m, double(top.position.y))), top.position.z},
                                      {}, top.color});
        }
        for (std::uint32_t k = 0; k + 1 < std::uint32_t(edge.size()); ++k) {
            const std::uint32_t a = base + 2 * k, b = a + 1, c = a + 2, d = a + 3;
            const glm::dvec3 middle = 0.5 * (glm::dvec3(mesh_.vertices[a].position) + glm::dvec3(mesh_.vertices[c].position));
            const glm::dvec3 out(middle.x - centre.x, 0.0, middle.z - centre.z);
            triangle(a, b, c, out);
            triangle(c, b, d, out);
        }
    }

    glm::dvec2 origin_m_;
    MeshData mesh_;
};

// n + 1 values from a to b.
std::vector<double> steps(double a, double b, int n)
{
    std::vector<double> values;
    for (int k = 0; k <= n; ++k)
        values.push_back(a + (b - a) * double(k) / double(n));
    return values;
}

// The bends with the lines where the colour changes (1 m under the sea's
// level) and every other line at most `spacing_m` apart, sorted.
std::vector<double> rowsAcross(std::vector<double> bends, double colourLine_u, double spacing_m)
{
    std::vector<double> rows;
    if (colourLine_u > bends.front() && colourLine_u < bends.back())
        bends.push_back(colourLine_u);
    std::sort(bends.begin(), bends.end());
    for (std::size_t k = 0; k + 1 < bends.size(); ++k) {
        const int n = std::max(1, int(std::ceil((bends[k + 1] - bends[k]) / spacing_m)));
        std::vector<double> part = steps(bends[k], bends[k + 1], n);
        rows.insert(rows.end(), part.begin(), part.end() - 1);
    }
    rows.push_back(bends.back());
    return rows;
}

// A shape's height at (u, v) of its frame, taken a micrometre inside its
// rectangle: on its very edge, rounding may put the point outside.
template <class Shape, class Elevation>
Sheet shoreSheet(const Shape& shape, const ShoreFrame& frame, const ShoreSpan& span, double toe_m,
                 double colourLine_u, Elevation elevation)
{
    constexpr double kInside_m = 1.0e-6;
    // Rows along the shore 1/16 of its length apart at most (lit per vertex).
    const double spacing_m = std::max(span.halfLength_m / 8.0, 1.0);
    Sheet sheet;
    sheet.us = rowsAcross(span.bends_u_m, colourLine_u, spacing_m);
    sheet.vs = steps(-span.halfLength_m, span.halfLength_m, std::max(1, int(std::ceil(2.0 * span.halfLength_m / spacing_m))));
    const double u0 = span.bends_u_m.front() + kInside_m, u1 = span.bends_u_m.back() - kInside_m;
    const double v1 = span.halfLength_m - kInside_m;
    sheet.point = [=, &shape](double u, double v) {
        const glm::dvec2 world = frame.world(u, v);
        const glm::dvec2 inside = frame.world(std::clamp(u, u0, u1), std::clamp(v, -v1, v1));
        return SheetPoint{world, elevation(shape, toe_m, inside).value_or(-toe_m)};
    };
    sheet.wallBottom_m = -toe_m;
    return sheet;
}

Sheet breakwaterSheet(const SeabedBreakwater& b, double toe_m)
{
    const double reach_m = breakwaterHalfFootprint_m(b, toe_m);
    const double length_m = glm::length(b.end_m - b.start_m);
    const glm::dvec2 along = (b.end_m - b.start_m) / length_m, across(-along.y, along.x);
    Sheet sheet;
    // Across: the toe, four steps down each side, the crest's edges; along:
    // six steps round each head.
    const double crest = 0.5 * b.crestWidth_m;
    sheet.vs = steps(-reach_m, -crest, 4);
    for (double v : steps(crest, reach_m, 4))
        sheet.vs.push_back(v);
    sheet.us = steps(-reach_m, 0.0, 6);
    sheet.us.pop_back();
    for (double u : steps(0.0, length_m, std::max(1, int(std::ceil(length_m / std::max(reach_m, 1.0))))))
        sheet.us.push_back(u);
    for (double u : steps(length_m, length_m + reach_m, 6))
        if (u > length_m)
            sheet.us.push_back(u);
    sheet.point = [=, &b](double u, double v) {
        const glm::dvec2 world = b.start_m + u * along + v * across;
        return SheetPoint{world, breakwaterElevation_m(b, toe_m, world).value_or(-toe_m)};
    };
    sheet.color = rockColor;
    return sheet;
}

Sheet heightmapSheet(const HeightGrid& grid)
{
    const auto samples = [](int pixels) {
        const int n = std::min(pixels, kMaxSeabedSheetSide) - 1;
        return steps(0.0, 1.0, n);
    };
    Sheet sheet;
    sheet.us = samples(grid.columns);
    sheet.vs = samples(grid.rows);
    sheet.point = [&grid](double u, double v) {
        // Clamped: min + 1 * (max - min) may round past max.
        const glm::dvec2 world =
            glm::clamp(grid.min_m + glm::dvec2(u, v) * (grid.max_m - grid.min_m), grid.min_m, grid.max_m);
        return SheetPoint{world, grid.at(world).value_or(0.0)};
    };
    return sheet;
}

} // namespace

SeabedMesh makeSeabedMesh(const Seabed& seabed)
{
    const Seabed::Data& d = seabed.data();
    std::optional<SeabedExtent> drawn;
    const auto cover = [&](const SeabedExtent& box) { drawn = drawn ? joined(*drawn, box) : box; };
    for (const SeabedExtent& box : d.beachBoxes)
        cover(box);
    for (const SeabedExtent& box : d.shelfBoxes)
        cover(box);
    for (const SeabedExtent& box : d.breakwaterBoxes)
        cover(box);
    if (d.heightmap)
        cover(d.heightmap->extent());
    if (!drawn)
        return {};
    MeshBuilder builder(0.5 * (drawn->min_m + drawn->max_m));
    for (const SeabedBeach& beach : d.shapes.beaches)
        builder.add(shoreSheet(beach, beachFrame(beach), beachSpan(beach, d.toe_m), d.toe_m, 1.0 / beach.slope,
                               beachElevation_m));
    for (const SeabedShelf& shelf : d.shapes.shelves)
        builder.add(shoreSheet(shelf, shelfFrame(shelf), shelfSpan(shelf, d.toe_m), d.toe_m,
                               (1.0 - shelf.depth_m) / shelf.slope, shelfElevation_m));
    for (const SeabedBreakwater& breakwater : d.shapes.breakwaters)
        builder.add(breakwaterSheet(breakwater, d.toe_m));
    if (d.heightmap)
        builder.add(heightmapSheet(*d.heightmap));
    return builder.finish();
}

} // namespace swell::detail
