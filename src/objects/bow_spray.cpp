// Where a hull under way throws spray from its bow (bow_spray.h).
#include "objects/bow_spray.h"

#include "objects/design_loading.h"
#include "swell/constants.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace swell::detail {

std::optional<BowLine> bowLineOf(const BodyShape& shape, double mass_kg, double density_kg_per_m3,
                                 glm::dvec3 forwardInShape, double speed_mps)
{
    const glm::dvec2 heading(forwardInShape.x, forwardInShape.z);
    if (shape.positions_m.empty() || glm::length(heading) < 1e-9 || !(mass_kg > 0.0))
        return std::nullopt;
    BowLine line;
    const glm::dvec2 f = glm::normalize(heading), a(-f.y, f.x);
    line.forward = {f.x, 0.0, f.y};
    line.across = {a.x, 0.0, a.y};
    // The waterline: the plane under which the hull displaces its mass, by
    // bisection (the volume below only grows with the plane's height).
    double lo = std::numeric_limits<double>::max(), hi = -lo;
    for (const glm::dvec3& p : shape.positions_m) {
        lo = std::min(lo, p.y);
        hi = std::max(hi, p.y);
    }
    const double top_m = hi;
    const double displaced_m3 = mass_kg / density_kg_per_m3;
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (volumeBelow(shape, mid).volume_m3 < displaced_m3 ? lo : hi) = mid;
    }
    line.waterline_m = 0.5 * (lo + hi);
    line.climb_m = std::min(speed_mps * speed_mps / (2.0 * kGravity), 0.5 * (top_m - line.waterline_m));
    // The hull cut at the climb: a segment for each triangle it crosses,
    // in (along, across) coordinates; the waterline's length from the cut
    // at the waterline itself.
    auto cutAt = [&](double y) {
        std::vector<std::pair<glm::dvec2, glm::dvec2>> cuts;
        for (std::size_t t = 0; t + 2 < shape.indices.size(); t += 3) {
            glm::dvec2 cut[3];
            int n = 0;
            for (int e = 0; e < 3; ++e) {
                const glm::dvec3 p = shape.positions_m[shape.indices[t + e]];
                const glm::dvec3 q = shape.positions_m[shape.indices[t + (e + 1) % 3]];
                if ((p.y < y) == (q.y < y))
                    continue;
                const glm::dvec3 c = p + (q - p) * ((y - p.y) / (q.y - p.y));
                if (n < 3)
                    cut[n++] = {glm::dot(glm::dvec2(c.x, c.z), f), glm::dot(glm::dvec2(c.x, c.z), a)};
            }
            if (n == 2)
                cuts.emplace_back(cut[0], cut[1]);
        }
        return cuts;
    };
    const std::vector<std::pair<glm::dvec2, glm::dvec2>> waterline = cutAt(line.waterline_m);
    const double y = line.waterline_m + line.climb_m;
    const std::vector<std::pair<glm::dvec2, glm::dvec2>> segments = cutAt(y);
    if (waterline.empty() || segments.empty())
        return std::nullopt;
    double fore = -std::numeric_limits<double>::max(), aft = std::numeric_limits<double>::max();
    for (const auto& [p, q] : waterline) {
        fore = std::max({fore, p.x, q.x});
        aft = std::min({aft, p.x, q.x});
    }
    line.length_m = fore - aft;
    glm::dvec2 stem(-std::numeric_limits<double>::max(), 0.0);
    for (const auto& [p, q] : segments)
        for (const glm::dvec2& c : {p, q})
            if (c.x > stem.x)
                stem = c;
    auto toShape = [&](double along, double side) {
        const glm::dvec2 xz = f * along + a * side;
        return glm::dvec3(xz.x, y, xz.y);
    };
    // A cut's outermost point on a side at a station (from `floor` out).
    auto breadthAt = [](const std::vector<std::pair<glm::dvec2, glm::dvec2>>& cuts, double along, double sign,
                        double floor) {
        double breadth = floor;
        for (const auto& [p, q] : cuts) {
            if ((p.x - along) * (q.x - along) > 0.0 || p.x == q.x)
                continue;
            const double across = p.y + (q.y - p.y) * ((along - p.x) / (q.x - p.x));
            breadth = std::max(breadth, across * sign);
        }
        return breadth;
    };
    double outboard_m = 0.0;
    int outboardStations = 0;
    for (int side = 0; side < 2; ++side) {
        const double sign = side == 0 ? 1.0 : -1.0;
        line.stations[side][0] = toShape(stem.x, stem.y);
        for (int k = 1; k < SWELL_BOW_SPRAY_STATIONS; ++k) {
            const double along =
                stem.x - SWELL_BOW_SPRAY_REACH * line.length_m * double(k) / (SWELL_BOW_SPRAY_STATIONS - 1);
            // The cut's outermost point on that side at this station, and
            // how far it lies outboard of the waterline's.
            const double breadth = breadthAt(segments, along, sign, stem.y * sign);
            // (A station ahead of the waterline's fore end has none there.)
            const double below = breadthAt(waterline, along, sign, -std::numeric_limits<double>::max());
            if (below > -std::numeric_limits<double>::max()) {
                outboard_m += breadth - below;
                ++outboardStations;
            }
            line.stations[side][k] = toShape(along, breadth * sign);
        }
    }
    if (line.climb_m > 1e-3 && outboardStations > 0)
        line.flareCot = std::max(outboard_m / outboardStations / line.climb_m, 0.0);
    return line;
}

double slamThreshold_mps(double length_m) { return 0.093 * std::sqrt(kGravity * std::max(length_m, 0.0)); }

double bowSprayShare(double speed_mps, double length_m, double plunge_mps)
{
    if (!(speed_mps > 0.0) || !(length_m > 0.0))
        return 0.0;
    const double froude = speed_mps / std::sqrt(kGravity * length_m);
    const double underWay = std::clamp(froude / 0.4, 0.0, 1.0);
    const double plunging = std::clamp(plunge_mps / slamThreshold_mps(length_m), 0.0, 1.0);
    return underWay * (0.2 + 0.8 * plunging);
}

BowSample bowSampleOf(const FloatingBody& body, const BowLine& line, glm::dvec2 velocity_m_per_s)
{
    const FloatingBody::PointMotion stem = body.pointAt(line.stations[0][0]);
    const FloatingBody::WaterMotion water = body.waterAt({stem.position_m.x, stem.position_m.z});
    const double plunge_mps = std::max(water.rise_m_per_s - stem.velocity_m_per_s.y, 0.0);
    BowSample s;
    s.share = float(bowSprayShare(glm::length(velocity_m_per_s), line.length_m, plunge_mps));
    s.plunge_mps = float(plunge_mps);
    s.leaves_m = float(water.height_m + line.climb_m);
    return s;
}

} // namespace swell::detail
