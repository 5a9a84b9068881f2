// The sea floor sampled (swell/scene/seabed.h): the scene's shapes, its
// heightmap, the island and a host's heights, each kept with its world
// rectangle so that a point far from a shape costs one comparison.
#include "assets/seabed_data.h"

#include "assets/grey_image.h"
#include "assets/island_terrain.h"
#include "swell/error.h"
#include "swell/scene/parameters.h"
#include "swell/scene/scene.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace swell {

namespace {

using detail::HeightGrid;

// The key as a scene file names it: "seabed.beaches[2].slope".
std::string shownKey(const Parameter& p, std::size_t item)
{
    if (p.list == ParameterList::None)
        return std::string(p.key);
    const std::string_view list = listKey(p.list);
    return fmt::format("{}[{}]{}", list, item, p.key.substr(list.size()));
}

[[noreturn]] void failAt(const Scene& scene, const std::string& key, const std::string& message)
{
    const auto place = scene.keyPlaces.find(key);
    throw InputError(place != scene.keyPlaces.end() ? place->second : SourcePlace{}, message);
}

// Every [seabed] key in its range (a scene file's reader has checked them;
// a scene made in code has not), and no breakwater without a length.
void checkSettings(const Scene& scene)
{
    for (const Parameter& p : parameters()) {
        if (!p.key.starts_with("seabed."))
            continue;
        for (std::size_t i = 0; i < listSize(scene, p.list); ++i) {
            const std::string key = shownKey(p, i);
            if (const std::string problem = valueProblem(p, p.get(scene, i), key); !problem.empty())
                failAt(scene, key, problem);
        }
    }
    if (const auto problem = detail::seabedShapeProblem(scene.seabed))
        failAt(scene, problem->key, problem->message);
}

// The heightmap's image as heights relative to the sea's mean level.
HeightGrid readHeightmap(const Scene& scene)
{
    const SeabedHeightmap& map = scene.seabed.heightmap;
    const std::string key = "seabed.heightmap.path";
    const std::filesystem::path path(map.path);
    const std::filesystem::path file =
        path.is_absolute() || scene.assetFolder.empty() ? path : std::filesystem::path(scene.assetFolder) / path;
    detail::GreyImage image;
    try {
        image = detail::readGreyImage(file);
    } catch (const InputError& e) {
        failAt(scene, key, fmt::format("{}: {}: {}", key, e.place().str(), e.message()));
    }
    if (image.width < 2 || image.height < 2)
        failAt(scene, key, fmt::format("{}: {}: the image is {}x{} pixels; a heightmap has at least 2x2", key,
                                       file.string(), image.width, image.height));
    HeightGrid grid{image.width, image.height, std::vector<float>(image.values.size()),
                    map.center_m - 0.5 * map.size_m, map.center_m + 0.5 * map.size_m};
    for (std::size_t i = 0; i < image.values.size(); ++i)
        grid.heights_m[i] =
            float(map.blackHeight_m + (map.whiteHeight_m - map.blackHeight_m) * (double(image.values[i]) / 65535.0));
    return grid;
}

void include(std::optional<SeabedExtent>& extent, const SeabedExtent& box)
{
    extent = extent ? detail::joined(*extent, box) : box;
}

SeabedExtent islandBox()
{
    const glm::dvec2 centre(detail::kIslandPosition_m.x, detail::kIslandPosition_m.z);
    return {centre - 0.5 * detail::kIslandSize_m, centre + 0.5 * detail::kIslandSize_m};
}

} // namespace

void checkSeabedHeights(const SeabedHeights& h, const std::string& what)
{
    constexpr int kMaxSide = 4096;
    if (h.columns < 2 || h.rows < 2 || h.columns > kMaxSide || h.rows > kMaxSide)
        throw Error(fmt::format("{}: the heights are {} x {}; each side must be 2..{}", what, h.columns, h.rows, kMaxSide));
    const std::size_t expected = std::size_t(h.columns) * std::size_t(h.rows);
    if (h.heights_m.size() != expected)
        throw Error(fmt::format("{}: {} x {} heights need {} values; the array holds {}", what, h.columns, h.rows,
                                expected, h.heights_m.size()));
    for (std::size_t i = 0; i < expected; ++i)
        if (!std::isfinite(h.heights_m[i]))
            throw Error(fmt::format("{}: height {} (column {}, row {}) is {}; heights must be finite", what, i,
                                    i % std::size_t(h.columns), i / std::size_t(h.columns), h.heights_m[i]));
    if (!(h.max_m.x > h.min_m.x && h.max_m.y > h.min_m.y) || !std::isfinite(h.min_m.x) || !std::isfinite(h.min_m.y)
        || !std::isfinite(h.max_m.x) || !std::isfinite(h.max_m.y))
        throw Error(fmt::format("{}: the rectangle [{}, {}]..[{}, {}] has no area; max_m must exceed min_m in x and z",
                                what, h.min_m.x, h.min_m.y, h.max_m.x, h.max_m.y));
}

Seabed::Seabed() : data_(std::make_shared<const Data>()) {}

Seabed::Seabed(const Scene& scene, const SeabedHeights* host)
{
    checkSettings(scene);
    if (host != nullptr)
        checkSeabedHeights(*host, "the host's seabed heights");
    Data d;
    d.floor_m = -scene.sea.depth_m;
    d.toe_m = std::min(scene.seabed.toeDepth_m, scene.sea.depth_m);
    d.shapes = scene.seabed;
    for (const SeabedBeach& b : d.shapes.beaches)
        include(d.extent, d.beachBoxes.emplace_back(detail::beachExtent(b, d.toe_m)));
    for (const SeabedShelf& s : d.shapes.shelves)
        include(d.extent, d.shelfBoxes.emplace_back(detail::shelfExtent(s, d.toe_m)));
    for (const SeabedBreakwater& b : d.shapes.breakwaters)
        include(d.extent, d.breakwaterBoxes.emplace_back(detail::breakwaterExtent(b, d.toe_m)));
    if (!scene.seabed.heightmap.path.empty())
        include(d.extent, d.heightmap.emplace(readHeightmap(scene)).extent());
    if (host != nullptr) {
        HeightGrid& grid = d.host.emplace(HeightGrid{host->columns, host->rows, host->heights_m, host->min_m, host->max_m});
        for (float& h : grid.heights_m)
            h = float(double(h) - scene.sea.level_m);
        include(d.extent, grid.extent());
    }
    d.island = scene.showTerrain;
    d.islandBase_m = detail::kIslandPosition_m.y;
    if (d.island)
        include(d.extent, islandBox());
    data_ = std::make_shared<const Data>(std::move(d));
}

double Seabed::elevation_m(glm::dvec2 p) const
{
    const Data& d = *data_;
    if (!d.extent || !detail::contains(*d.extent, p))
        return d.floor_m;
    double highest = d.floor_m;
    const auto take = [&](std::optional<double> h) {
        if (h)
            highest = std::max(highest, *h);
    };
    for (std::size_t i = 0; i < d.beachBoxes.size(); ++i)
        if (detail::contains(d.beachBoxes[i], p))
            take(beachElevation_m(d.shapes.beaches[i], d.toe_m, p));
    for (std::size_t i = 0; i < d.shelfBoxes.size(); ++i)
        if (detail::contains(d.shelfBoxes[i], p))
            take(shelfElevation_m(d.shapes.shelves[i], d.toe_m, p));
    for (std::size_t i = 0; i < d.breakwaterBoxes.size(); ++i)
        if (detail::contains(d.breakwaterBoxes[i], p))
            take(breakwaterElevation_m(d.shapes.breakwaters[i], d.toe_m, p));
    if (d.heightmap)
        take(d.heightmap->at(p));
    if (d.host)
        take(d.host->at(p));
    if (d.island && detail::contains(islandBox(), p)) {
        const glm::dvec2 centre(detail::kIslandPosition_m.x, detail::kIslandPosition_m.z);
        take(d.islandBase_m + detail::islandHeight_m(p - centre, detail::kIslandSize_m, detail::kIslandPeak_m));
    }
    return highest;
}

std::optional<SeabedExtent> Seabed::extent() const { return data_->extent; }

double Seabed::toeDepth_m() const { return data_->toe_m; }

} // namespace swell
