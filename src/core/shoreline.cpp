// The water's edge in a frame's labels (swell/dataset/labels.h,
// measureShoreline): the sides between water and land pixels, chained.
#include "swell/dataset/labels.h"
#include "swell/dataset/sensor.h"
#include "swell/gpu/label_classes.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace swell {

namespace {

bool isWater(std::uint16_t s) { return isSeaClass(s); }

bool isLand(std::uint16_t s) { return isGroundClass(s); }

// The pixel grid's corners as one index, and the sides between them.
struct Corners {
    int columns; // corners along x: the width + 1
    std::int64_t id(int x, int y) const { return std::int64_t(y) * columns + x; }
    glm::ivec2 at(std::int64_t id) const { return {int(id % columns), int(id / columns)}; }
};

std::uint64_t sideKey(std::int64_t a, std::int64_t b)
{
    const std::uint64_t lo = std::uint64_t(std::min(a, b)), hi = std::uint64_t(std::max(a, b));
    return (hi << 32) ^ lo;
}

// The water's point at corner (x, y): a water pixel among the four that
// share it, along its centre ray at its range.
glm::dvec3 waterPointAt(const FrameLabels& labels, glm::ivec2 corner)
{
    const CameraCalibration& c = labels.camera;
    const LensDistortion lens = lensOf(c);
    const glm::dvec3 eye(c.worldFromCamera[3]);
    for (const glm::ivec2 d : {glm::ivec2(-1, -1), glm::ivec2(0, -1), glm::ivec2(-1, 0), glm::ivec2(0, 0)}) {
        const glm::ivec2 p = corner + d;
        if (p.x < 0 || p.y < 0 || p.x >= labels.size.x || p.y >= labels.size.y)
            continue;
        const std::size_t i = std::size_t(p.y) * std::size_t(labels.size.x) + std::size_t(p.x);
        if (!isWater(labels.semantic[i]))
            continue;
        const double range_m = labels.range_m[i];
        if (!std::isfinite(range_m))
            break;
        const glm::dvec2 u = undistort(lens, {(p.x + 0.5 - c.cx_px) / c.fx_px, (p.y + 0.5 - c.cy_px) / c.fy_px});
        const glm::dvec3 ray = glm::normalize(glm::dmat3(c.worldFromCamera) * glm::dvec3(u, 1.0));
        return eye + range_m * ray;
    }
    return glm::dvec3(std::numeric_limits<double>::quiet_NaN());
}

} // namespace

void measureShoreline(FrameLabels& labels)
{
    labels.shoreline.clear();
    const int w = labels.size.x, h = labels.size.y;
    const std::size_t count = std::size_t(std::max(w, 0)) * std::size_t(std::max(h, 0));
    if (w < 1 || h < 1 || labels.semantic.size() != count || labels.range_m.size() != count)
        return;
    const Corners corners{w + 1};
    std::unordered_map<std::int64_t, std::vector<std::int64_t>> links;
    auto shoreBetween = [&](std::size_t a, std::size_t b) {
        const std::uint16_t sa = labels.semantic[a], sb = labels.semantic[b];
        return (isWater(sa) && isLand(sb)) || (isLand(sa) && isWater(sb));
    };
    auto link = [&](std::int64_t a, std::int64_t b) {
        links[a].push_back(b);
        links[b].push_back(a);
    };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
            if (x + 1 < w && shoreBetween(i, i + 1)) // the side between (x, y) and (x + 1, y)
                link(corners.id(x + 1, y), corners.id(x + 1, y + 1));
            if (y + 1 < h && shoreBetween(i, i + std::size_t(w))) // between (x, y) and (x, y + 1)
                link(corners.id(x, y + 1), corners.id(x + 1, y + 1));
        }
    // Chains from each end (a corner with one side, or three or more),
    // then the closed loops left.
    std::unordered_set<std::uint64_t> walked;
    auto walk = [&](std::int64_t start) {
        for (const std::int64_t first : links[start]) {
            if (walked.count(sideKey(start, first)))
                continue;
            ShoreLine line;
            std::int64_t at = first;
            line.points_px.push_back(glm::dvec2(corners.at(start)));
            walked.insert(sideKey(start, at));
            for (;;) {
                line.points_px.push_back(glm::dvec2(corners.at(at)));
                const std::vector<std::int64_t>& next = links[at];
                std::int64_t onward = -1;
                if (next.size() == 2)
                    for (const std::int64_t n : next)
                        if (!walked.count(sideKey(at, n)))
                            onward = n;
                if (onward < 0)
                    break;
                walked.insert(sideKey(at, onward));
                at = onward;
            }
            for (const glm::dvec2& p : line.points_px)
                line.points_m.push_back(waterPointAt(labels, glm::ivec2(p)));
            labels.shoreline.push_back(std::move(line));
        }
    };
    std::vector<std::int64_t> ends, all;
    for (const auto& [corner, sides] : links) {
        all.push_back(corner);
        if (sides.size() != 2)
            ends.push_back(corner);
    }
    // In the image's order, so that the same labels give the same chains.
    std::sort(ends.begin(), ends.end());
    std::sort(all.begin(), all.end());
    for (const std::int64_t e : ends)
        walk(e);
    for (const std::int64_t c : all)
        walk(c);
}

} // namespace swell
