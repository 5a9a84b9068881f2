// `swell bench`: how well the water grid's level of detail fits one view.
// Take the vertices the water shader really produces (transform feedback) and
// the triangles the renderer draws for that view (the grid tiles it did not
// cull), project them with the renderer's view-projection, and count those
// that reach the view frustum and their size on screen.
#include "bench.h"

#include "swell/error.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace swell::app::bench {

namespace {

// Bits of the clip-space planes a point lies outside of.
unsigned outcode(const glm::dvec4& c)
{
    unsigned code = 0;
    if (c.x < -c.w) code |= 1u;
    if (c.x > c.w) code |= 2u;
    if (c.y < -c.w) code |= 4u;
    if (c.y > c.w) code |= 8u;
    if (c.z < -c.w) code |= 16u;
    if (c.z > c.w) code |= 32u;
    return code;
}

struct ScreenSize {
    double area_px2 = 0.0;
    double longestEdge_px = 0.0;
};

// The triangle's size on screen once the part behind the near plane
// (z < -w) is cut away; the part beyond the screen's edges still counts.
ScreenSize screenSize(const std::array<glm::dvec4, 3>& triangle, glm::ivec2 size)
{
    // Sutherland-Hodgman against the near plane: up to 4 corners.
    std::array<glm::dvec4, 4> polygon;
    int n = 0;
    for (int i = 0; i < 3; ++i) {
        const glm::dvec4& a = triangle[size_t(i)];
        const glm::dvec4& b = triangle[size_t((i + 1) % 3)];
        const double da = a.z + a.w, db = b.z + b.w;
        if (da >= 0.0)
            polygon[size_t(n++)] = a;
        if ((da >= 0.0) != (db >= 0.0))
            polygon[size_t(n++)] = a + (b - a) * (da / (da - db));
    }
    ScreenSize out;
    if (n < 3)
        return out;
    std::array<glm::dvec2, 4> screen;
    for (int i = 0; i < n; ++i) {
        const glm::dvec4& c = polygon[size_t(i)];
        screen[size_t(i)] = {(c.x / c.w * 0.5 + 0.5) * size.x, (c.y / c.w * 0.5 + 0.5) * size.y};
    }
    double twiceArea = 0.0;
    for (int i = 0; i < n; ++i) {
        const glm::dvec2& a = screen[size_t(i)];
        const glm::dvec2& b = screen[size_t((i + 1) % n)];
        twiceArea += a.x * b.y - b.x * a.y;
        out.longestEdge_px = std::max(out.longestEdge_px, glm::length(b - a));
    }
    out.area_px2 = 0.5 * std::abs(twiceArea);
    return out;
}

} // namespace

LodSample measureLod(const std::vector<float>& vertices, int vertexCount, const std::vector<std::uint32_t>& triangles,
                     const glm::dmat4& viewProj, glm::ivec2 size)
{
    constexpr int kFloatsPerVertex = 8; // restPoint.xz, position xyz, normal xyz
    if (vertexCount < 3 || vertices.size() < size_t(vertexCount) * kFloatsPerVertex || triangles.size() % 3 != 0 ||
        std::any_of(triangles.begin(), triangles.end(), [&](std::uint32_t v) { return v >= std::uint32_t(vertexCount); }))
        throw Error(fmt::format("swell bench: {} water triangles do not index {} vertices", triangles.size() / 3, vertexCount));

    std::vector<glm::dvec4> clip(static_cast<size_t>(vertexCount));
    std::vector<unsigned> codes(static_cast<size_t>(vertexCount));
    for (size_t v = 0; v < clip.size(); ++v) {
        const float* p = &vertices[v * kFloatsPerVertex + 2];
        clip[v] = viewProj * glm::dvec4(p[0], p[1], p[2], 1.0);
        codes[v] = outcode(clip[v]);
    }

    LodSample out;
    std::vector<double> areas, edges;
    auto addTriangle = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        ++out.triangles;
        if (codes[a] & codes[b] & codes[c])
            return; // wholly outside one plane of the frustum
        ++out.inFrustum;
        const ScreenSize s = screenSize({clip[a], clip[b], clip[c]}, size);
        areas.push_back(s.area_px2);
        edges.push_back(s.longestEdge_px);
    };
    for (size_t t = 0; t < triangles.size(); t += 3)
        addTriangle(triangles[t], triangles[t + 1], triangles[t + 2]);

    out.inFrustumShare = out.triangles > 0 ? double(out.inFrustum) / double(out.triangles) : 0.0;
    if (!areas.empty()) {
        out.subPixelShare = double(std::count_if(areas.begin(), areas.end(), [](double a) { return a < 1.0; })) /
                            double(areas.size());
        out.areaP10_px2 = percentile(areas, 0.10);
        out.areaP90_px2 = percentile(areas, 0.90);
        out.areaMedian_px2 = median(areas);
        out.edgeMedian_px = median(edges);
    }
    return out;
}

} // namespace swell::app::bench
