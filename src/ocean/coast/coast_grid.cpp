// The scene's depth grid for the coast field (coast_grid.h).
#include "ocean/coast/coast_grid.h"

#include "ocean/coast/coast_cache.h"

#include "swell/scene/seabed.h"
#include "swell/scene/waves.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <deque>
#include <mutex>

namespace swell::coast {

namespace {

bool sameWaves(const WaveSet& a, const WaveSet& b) { return a.waves == b.waves && a.depth_m == b.depth_m; }

bool sameGrid(const DepthGrid& a, const DepthGrid& b)
{
    return a.origin_m == b.origin_m && a.cell_m == b.cell_m && a.size == b.size && a.outsideDepth_m == b.outsideDepth_m
           && a.depth_m == b.depth_m;
}

std::shared_ptr<const CoastField> keptFieldOf(const WaveSet& waves, DepthGrid grid)
{
    struct Entry {
        WaveSet waves;
        std::shared_ptr<const CoastField> field;
    };
    static std::mutex mutex;
    static std::deque<Entry> kept;
    constexpr std::size_t kKept = 4;
    {
        const std::lock_guard lock(mutex);
        for (const Entry& e : kept)
            if (sameWaves(e.waves, waves) && sameGrid(e.field->depth(), grid))
                return e.field;
    }
    auto field = solvedOrCachedField(waves, std::move(grid));
    const std::lock_guard lock(mutex);
    kept.push_front({waves, field});
    if (kept.size() > kKept)
        kept.pop_back();
    return field;
}

} // namespace

std::optional<DepthGrid> depthGridOf(const Seabed& seabed, const WaveSet& waves)
{
    const std::optional<SeabedExtent> extent = seabed.extent();
    if (!extent || waves.waves.empty())
        return std::nullopt;
    double longest = 0.0;
    for (const Wave& w : waves.waves)
        longest = std::max(longest, w.wavelength_m);
    const double margin = std::clamp(longest, 150.0, 600.0);
    const glm::dvec2 lo = extent->min_m - margin, hi = extent->max_m + margin;
    const double side = std::max(hi.x - lo.x, hi.y - lo.y);
    DepthGrid grid;
    grid.cell_m = std::max(kFinestCell_m, side / double(kSceneGridSide - 1));
    grid.size = glm::ivec2(glm::ceil((hi - lo) / grid.cell_m)) + 1;
    grid.size = glm::min(grid.size, glm::ivec2(kSceneGridSide));
    grid.origin_m = lo;
    grid.outsideDepth_m = waves.depth_m;
    grid.depth_m.resize(std::size_t(grid.size.x) * std::size_t(grid.size.y));
    for (int j = 0; j < grid.size.y; ++j)
        for (int i = 0; i < grid.size.x; ++i) {
            const double elevation = seabed.elevation_m(grid.origin_m + grid.cell_m * glm::dvec2(i, j));
            // A floor deeper than the open sea's is the open sea (and -inf, deep water, fits no float).
            const double depth = std::min(-elevation, std::isinf(waves.depth_m) ? 1.0e4 : waves.depth_m);
            grid.depth_m[std::size_t(j) * std::size_t(grid.size.x) + std::size_t(i)] = float(depth);
        }
    return grid;
}

std::shared_ptr<const CoastField> coastFieldOf(const Seabed& seabed, const WaveSet& waves)
{
    std::optional<DepthGrid> grid = depthGridOf(seabed, waves);
    if (!grid)
        return nullptr;
    return keptFieldOf(waves, std::move(*grid));
}

} // namespace swell::coast
