// The seabed's analytic shapes (core/seabed_shapes.h, swell/scene/seabed.h).
#include "core/seabed_shapes.h"

#include <fmt/format.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace swell {

glm::dvec2 azimuthDirection(double azimuth_deg)
{
    const double a = glm::radians(azimuth_deg);
    return {std::sin(a), -std::cos(a)};
}

namespace detail {

namespace {

ShoreFrame frameOf(glm::dvec2 origin_m, double seawardAzimuth_deg)
{
    const glm::dvec2 seaward = azimuthDirection(seawardAzimuth_deg);
    return {origin_m, seaward, {-seaward.y, seaward.x}};
}

// The point's place in the frame: {u, v}, m.
glm::dvec2 local(const ShoreFrame& frame, glm::dvec2 world_xz_m)
{
    const glm::dvec2 d = world_xz_m - frame.origin_m;
    return {glm::dot(d, frame.seaward), glm::dot(d, frame.along)};
}

SeabedExtent spanExtent(const ShoreFrame& frame, const ShoreSpan& span)
{
    const double u0 = span.bends_u_m.front(), u1 = span.bends_u_m.back(), v = span.halfLength_m;
    return boundsOf({frame.world(u0, -v), frame.world(u0, v), frame.world(u1, -v), frame.world(u1, v)});
}

// The distance from p to the segment a-b, m.
double distanceToSegment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b)
{
    const glm::dvec2 ab = b - a;
    const double length2 = glm::dot(ab, ab);
    const double t = length2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

} // namespace

ShoreFrame beachFrame(const SeabedBeach& beach) { return frameOf(beach.shorePoint_m, beach.seawardAzimuth_deg); }
ShoreFrame shelfFrame(const SeabedShelf& shelf) { return frameOf(shelf.edgePoint_m, shelf.seawardAzimuth_deg); }

// Bends: the back of the land, the top, the shoreline, the toe.
ShoreSpan beachSpan(const SeabedBeach& beach, double toe_m)
{
    const double top_u = -beach.top_m / beach.slope;
    return {0.5 * beach.length_m, {top_u - beach.landWidth_m, top_u, 0.0, toe_m / beach.slope}};
}

// Bends: the back of the flat top, the edge's top line, the toe (none when
// the top lies at the toe's depth or deeper: the shelf is all flat).
ShoreSpan shelfSpan(const SeabedShelf& shelf, double toe_m)
{
    ShoreSpan span{0.5 * shelf.length_m, {-shelf.width_m, 0.0}};
    if (shelf.depth_m < toe_m)
        span.bends_u_m.push_back((toe_m - shelf.depth_m) / shelf.slope);
    return span;
}

double breakwaterHalfFootprint_m(const SeabedBreakwater& breakwater, double toe_m)
{
    return 0.5 * breakwater.crestWidth_m + std::max(0.0, breakwater.crest_m + toe_m) / breakwater.sideSlope;
}

SeabedExtent boundsOf(const std::vector<glm::dvec2>& corners)
{
    SeabedExtent box{corners.front(), corners.front()};
    for (const glm::dvec2& c : corners)
        box = {glm::min(box.min_m, c), glm::max(box.max_m, c)};
    return box;
}

SeabedExtent beachExtent(const SeabedBeach& beach, double toe_m)
{
    return spanExtent(beachFrame(beach), beachSpan(beach, toe_m));
}

SeabedExtent shelfExtent(const SeabedShelf& shelf, double toe_m)
{
    return spanExtent(shelfFrame(shelf), shelfSpan(shelf, toe_m));
}

SeabedExtent breakwaterExtent(const SeabedBreakwater& breakwater, double toe_m)
{
    const glm::dvec2 reach(breakwaterHalfFootprint_m(breakwater, toe_m));
    return {glm::min(breakwater.start_m, breakwater.end_m) - reach, glm::max(breakwater.start_m, breakwater.end_m) + reach};
}

bool contains(const SeabedExtent& box, glm::dvec2 p)
{
    return p.x >= box.min_m.x && p.x <= box.max_m.x && p.y >= box.min_m.y && p.y <= box.max_m.y;
}

SeabedExtent joined(const SeabedExtent& a, const SeabedExtent& b)
{
    return {glm::min(a.min_m, b.min_m), glm::max(a.max_m, b.max_m)};
}

std::optional<double> HeightGrid::at(glm::dvec2 p) const
{
    if (!contains(extent(), p))
        return std::nullopt;
    // In samples: column 0 at min_m.x, column columns - 1 at max_m.x.
    const glm::dvec2 s = (p - min_m) / (max_m - min_m) * glm::dvec2(columns - 1, rows - 1);
    const int i = std::min(int(s.x), columns - 2), j = std::min(int(s.y), rows - 2);
    const double fx = s.x - i, fz = s.y - j;
    const auto h = [&](int c, int r) { return double(heights_m[std::size_t(r) * std::size_t(columns) + std::size_t(c)]); };
    const double north = h(i, j) + (h(i + 1, j) - h(i, j)) * fx;
    const double south = h(i, j + 1) + (h(i + 1, j + 1) - h(i, j + 1)) * fx;
    return north + (south - north) * fz;
}

std::optional<SeabedProblem> seabedShapeProblem(const SeabedSettings& seabed)
{
    for (std::size_t i = 0; i < seabed.breakwaters.size(); ++i) {
        const SeabedBreakwater& b = seabed.breakwaters[i];
        if (b.start_m == b.end_m)
            return SeabedProblem{fmt::format("seabed.breakwaters[{}].end_m", i),
                                 fmt::format("seabed.breakwaters[{}] has no length: end_m = start_m = [{}, {}]; a "
                                             "breakwater runs from start_m to another point end_m",
                                             i, b.start_m.x, b.start_m.y)};
    }
    return std::nullopt;
}

} // namespace detail

std::optional<double> beachElevation_m(const SeabedBeach& beach, double toe_m, glm::dvec2 world_xz_m)
{
    const glm::dvec2 at = detail::local(detail::beachFrame(beach), world_xz_m);
    const detail::ShoreSpan span = detail::beachSpan(beach, toe_m);
    if (std::abs(at.y) > span.halfLength_m || at.x < span.bends_u_m.front() || at.x > span.bends_u_m.back())
        return std::nullopt;
    return std::clamp(-beach.slope * at.x, -toe_m, beach.top_m);
}

std::optional<double> shelfElevation_m(const SeabedShelf& shelf, double toe_m, glm::dvec2 world_xz_m)
{
    const glm::dvec2 at = detail::local(detail::shelfFrame(shelf), world_xz_m);
    const detail::ShoreSpan span = detail::shelfSpan(shelf, toe_m);
    if (std::abs(at.y) > span.halfLength_m || at.x < span.bends_u_m.front() || at.x > span.bends_u_m.back())
        return std::nullopt;
    return -shelf.depth_m - shelf.slope * std::max(at.x, 0.0);
}

std::optional<double> breakwaterElevation_m(const SeabedBreakwater& breakwater, double toe_m, glm::dvec2 world_xz_m)
{
    const double d = detail::distanceToSegment(world_xz_m, breakwater.start_m, breakwater.end_m);
    if (d > detail::breakwaterHalfFootprint_m(breakwater, toe_m))
        return std::nullopt;
    return breakwater.crest_m - breakwater.sideSlope * std::max(0.0, d - 0.5 * breakwater.crestWidth_m);
}

} // namespace swell
