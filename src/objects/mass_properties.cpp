// Volume, centroid and inertia of a closed triangle mesh (swell/floating_body.h).
//
// Each triangle (a, b, c) and the origin span a tetrahedron of signed volume
// det[a b c] / 6; summed over a closed surface they give the enclosed volume
// whatever the origin. The covariance integral C = int x x^T dV of each
// tetrahedron is det[a b c] * A C0 A^T, A = [a b c], with C0 the canonical
// tetrahedron's (Blow & Binstock 2004, "How to find the inertia tensor (or
// other mass properties) of a 3D solid body represented by a triangle mesh",
// eq. for C_canonical = [[1/60, 1/120, 1/120], ...]); moved to the centroid,
// C' = C - V c c^T, and the inertia is trace(C') I - C'.
#include "swell/floating_body.h"

#include "swell/error.h"

#include <fmt/format.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace swell {

namespace {

// Vertices closer than this fraction of the mesh's extent are one: seams of
// float meshes (a lathe's last column at 2 pi, 1e-7 off its first) close.
constexpr double kWeldFraction = 1e-5;

// Every edge of a closed, consistently wound surface is walked once each way.
// Vertices are compared by position (welded on a lattice of kWeldFraction of
// the extent), so a model whose faces have their own vertices (for flat
// normals) still counts as closed.
void checkClosed(const BodyShape& shape)
{
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (const glm::dvec3& p : shape.positions_m) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const double weld_m = kWeldFraction * std::max(glm::length(hi - lo), 1e-9);
    // Welded ids by sorting the lattice points (flat arrays: a model at the
    // loader's vertex cap stays within tens of MB here).
    using Key = std::array<std::int64_t, 3>;
    std::vector<std::pair<Key, std::uint32_t>> keyed(shape.positions_m.size());
    for (std::size_t i = 0; i < keyed.size(); ++i) {
        const glm::dvec3 q = glm::round((shape.positions_m[i] - lo) / weld_m);
        keyed[i] = {Key{std::int64_t(q.x), std::int64_t(q.y), std::int64_t(q.z)}, std::uint32_t(i)};
    }
    std::sort(keyed.begin(), keyed.end());
    std::vector<std::uint32_t> id(keyed.size());
    std::uint32_t next = 0;
    for (std::size_t i = 0; i < keyed.size(); ++i) {
        if (i > 0 && keyed[i].first != keyed[i - 1].first)
            ++next;
        id[keyed[i].second] = next;
    }
    std::vector<std::pair<std::uint32_t, std::uint32_t>> directed;
    directed.reserve(shape.indices.size());
    for (std::size_t t = 0; t + 2 < shape.indices.size(); t += 3) {
        const std::uint32_t v[3] = {id[shape.indices[t]], id[shape.indices[t + 1]], id[shape.indices[t + 2]]};
        if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0])
            continue; // degenerate: adds no area
        for (int e = 0; e < 3; ++e)
            directed.emplace_back(v[e], v[(e + 1) % 3]);
    }
    std::sort(directed.begin(), directed.end());
    auto count = [&](std::pair<std::uint32_t, std::uint32_t> edge) {
        const auto range = std::equal_range(directed.begin(), directed.end(), edge);
        return int(range.second - range.first);
    };
    for (std::size_t i = 0; i < directed.size(); ++i) {
        const int forth = (i + 1 < directed.size() && directed[i + 1] == directed[i]) ? 2 : 1;
        const int back = count({directed[i].second, directed[i].first});
        if (forth != 1 || back != 1)
            throw InputError({}, fmt::format("the body's mesh is not closed: an edge is used by {} triangle(s) one "
                                             "way and {} the other (a closed, consistently wound surface uses each "
                                             "edge once each way)",
                                             forth == 1 ? 1 : count(directed[i]), back));
    }
}

} // namespace

MassProperties massPropertiesOf(const BodyShape& shape)
{
    if (shape.indices.size() < 12 || shape.indices.size() % 3 != 0)
        throw InputError({}, fmt::format("the body's mesh has {} indices; a closed surface needs at least 4 "
                                         "triangles",
                                         shape.indices.size()));
    for (std::uint32_t i : shape.indices)
        if (i >= shape.positions_m.size())
            throw InputError({}, fmt::format("the body's mesh names vertex {} of {}", i, shape.positions_m.size()));
    checkClosed(shape);

    // Blow & Binstock (2004): the canonical tetrahedron's covariance.
    const glm::dmat3 canonical = glm::dmat3(2.0, 1.0, 1.0, 1.0, 2.0, 1.0, 1.0, 1.0, 2.0) / 120.0;
    double volume = 0.0;
    glm::dvec3 moment(0.0);
    glm::dmat3 covariance(0.0);
    for (std::size_t t = 0; t < shape.indices.size(); t += 3) {
        const glm::dvec3 a = shape.positions_m[shape.indices[t]];
        const glm::dvec3 b = shape.positions_m[shape.indices[t + 1]];
        const glm::dvec3 c = shape.positions_m[shape.indices[t + 2]];
        const glm::dmat3 A(a, b, c); // columns
        const double det = glm::dot(a, glm::cross(b, c));
        volume += det / 6.0;
        moment += det / 6.0 * (a + b + c) / 4.0;
        covariance += det * A * canonical * glm::transpose(A);
    }
    // A surface wound inside out encloses a negative volume. Its faces point
    // into the body: drawn, it shows its inside and is lit from within, so
    // it is refused rather than turned silently (docs/BODIES.md).
    if (volume < -1e-12 && std::isfinite(volume))
        throw InputError({}, fmt::format("the body's mesh is wound inside out: its triangles face inwards (it "
                                         "encloses {:.6g} m^3); reverse their winding (counter-clockwise seen from "
                                         "outside, as glTF's front faces are)",
                                         volume));
    if (!(volume > 1e-12) || !std::isfinite(volume))
        throw InputError({}, fmt::format("the body's mesh encloses no volume ({} m^3)", volume));
    MassProperties m;
    m.volume_m3 = volume;
    m.centroid_m = moment / volume;
    const glm::dmat3 about = covariance - volume * glm::outerProduct(m.centroid_m, m.centroid_m);
    m.inertiaAboutCentroid_kg_m2 = (about[0][0] + about[1][1] + about[2][2]) * glm::dmat3(1.0) - about;
    return m;
}

} // namespace swell
