// A hull simplified for its hydrostatics (hull_simplify.h).
#include "objects/hull_simplify.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <unordered_map>

namespace swell::detail {

namespace {

// The hull clustered on cells of `cell_m`: each occupied cell's vertices
// merged at their mean, triangles whose corners share a cell dropped, and a
// triangle and its reverse (the two sides of a sliver) cancelled.
BodyShape clustered(const BodyShape& shape, glm::dvec3 origin_m, double cell_m)
{
    std::unordered_map<std::uint64_t, std::uint32_t> cellOf;
    std::vector<glm::dvec3> sum;
    std::vector<double> count;
    std::vector<std::uint32_t> vertexCluster(shape.positions_m.size());
    for (std::size_t v = 0; v < shape.positions_m.size(); ++v) {
        const glm::dvec3 c = glm::floor((shape.positions_m[v] - origin_m) / cell_m);
        // 21 bits an axis: a hull spans far fewer cells than 2^21 at any cell size chosen below.
        const std::uint64_t key = (std::uint64_t(c.x) & 0x1fffff) | (std::uint64_t(c.y) & 0x1fffff) << 21 |
                                  (std::uint64_t(c.z) & 0x1fffff) << 42;
        const auto [at, added] = cellOf.try_emplace(key, std::uint32_t(sum.size()));
        if (added) {
            sum.emplace_back(0.0);
            count.push_back(0.0);
        }
        sum[at->second] += shape.positions_m[v];
        count[at->second] += 1.0;
        vertexCluster[v] = at->second;
    }
    // Each triangle as its corners' clusters, rotated to start at the
    // smallest, so that a triangle and its reverse meet as one key.
    std::map<std::array<std::uint32_t, 3>, int> triangles;
    for (std::size_t t = 0; t + 2 < shape.indices.size(); t += 3) {
        std::array<std::uint32_t, 3> c = {vertexCluster[shape.indices[t]], vertexCluster[shape.indices[t + 1]],
                                          vertexCluster[shape.indices[t + 2]]};
        if (c[0] == c[1] || c[1] == c[2] || c[2] == c[0])
            continue;
        std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
        const bool reversed = c[1] > c[2];
        if (reversed)
            std::swap(c[1], c[2]);
        triangles[c] += reversed ? -1 : 1;
    }
    BodyShape out;
    out.positions_m.resize(sum.size());
    for (std::size_t i = 0; i < sum.size(); ++i)
        out.positions_m[i] = sum[i] / count[i];
    for (const auto& [c, n] : triangles)
        for (int k = 0; k < std::abs(n); ++k) {
            out.indices.push_back(c[0]);
            out.indices.push_back(n > 0 ? c[1] : c[2]);
            out.indices.push_back(n > 0 ? c[2] : c[1]);
        }
    return out;
}

} // namespace

double enclosedVolume(const BodyShape& shape)
{
    double six = 0.0;
    for (std::size_t t = 0; t + 2 < shape.indices.size(); t += 3) {
        const glm::dvec3 &a = shape.positions_m[shape.indices[t]], &b = shape.positions_m[shape.indices[t + 1]],
                         &c = shape.positions_m[shape.indices[t + 2]];
        six += glm::dot(a, glm::cross(b, c));
    }
    return six / 6.0;
}

BodyShape hydrostaticHull(const BodyShape& shape, double volume_m3, glm::dvec3 centroid_m, std::size_t maxTriangles)
{
    if (shape.indices.size() / 3 <= maxTriangles)
        return shape;
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
    for (const glm::dvec3& p : shape.positions_m) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    // A closed surface clustered on cells of size h keeps about 2 area / h^2
    // triangles: cells from a little finer than that, each try 1.25 times
    // coarser, until the triangles fit.
    double area_m2 = 0.0;
    for (std::size_t t = 0; t + 2 < shape.indices.size(); t += 3) {
        const glm::dvec3 &a = shape.positions_m[shape.indices[t]], &b = shape.positions_m[shape.indices[t + 1]],
                         &c = shape.positions_m[shape.indices[t + 2]];
        area_m2 += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    const double longest = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 1e-9});
    BodyShape out;
    for (double cell = std::max(0.8 * std::sqrt(2.0 * area_m2 / double(maxTriangles)), longest / 1e5);; cell *= 1.25) {
        out = clustered(shape, lo, cell);
        if (out.indices.size() / 3 <= maxTriangles)
            break;
    }
    // Scaled about the full hull's centroid to its volume: the merged
    // vertices lie inside a convex stretch of the surface, so the clustered
    // hull encloses a little less.
    const double v = enclosedVolume(out);
    if (v > 0.0) {
        const double scale = std::cbrt(volume_m3 / v);
        for (glm::dvec3& p : out.positions_m)
            p = centroid_m + scale * (p - centroid_m);
    }
    return out;
}

} // namespace swell::detail
