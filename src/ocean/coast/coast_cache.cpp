#include "ocean/coast/coast_cache.h"

#include "core/derived_cache.h"
#include "swell/constants.h"
#include "swell/scene/waves.h"

#include <optional>
#include <span>

namespace swell {

namespace detail {

// What a field's solve is keyed by, and what it keeps: the texels and the
// reach. The grid is the key's and is not kept twice.
struct CoastFieldBytes {
    static CacheBytes keyOf(const WaveSet& waves, const DepthGrid& grid, double breakerIndex)
    {
        CacheBytes key;
        key.add(std::uint64_t(waves.waves.size()));
        for (const Wave& w : waves.waves) {
            key.add(w.direction.x);
            key.add(w.direction.y);
            key.add(w.wavelength_m);
            key.add(w.amplitude_m);
            key.add(w.steepness);
            key.add(w.phase_rad);
        }
        key.add(waves.depth_m);
        key.add(grid.origin_m.x);
        key.add(grid.origin_m.y);
        key.add(grid.cell_m);
        key.add(grid.size.x);
        key.add(grid.size.y);
        key.add(grid.outsideDepth_m);
        key.addSpan(std::span<const float>(grid.depth_m));
        key.add(breakerIndex);
        return key;
    }

    static CacheBytes texelsOf(const CoastField& field)
    {
        CacheBytes kept;
        kept.addSpan(std::span<const int>(field.layerOfWave_));
        kept.add(std::uint64_t(field.layers_.size()));
        for (const std::vector<glm::vec4>& layer : field.layers_)
            kept.addSpan(std::span<const glm::vec4>(layer));
        kept.addSpan(std::span<const glm::vec4>(field.common_));
        kept.add(field.reach_.vertical_m);
        kept.add(field.reach_.horizontal_m);
        return kept;
    }

    // None unless the bytes are a whole field of these waves over this grid.
    static std::shared_ptr<const CoastField> fieldOf(std::span<const std::byte> bytes, const WaveSet& waves,
                                                      DepthGrid grid)
    {
        const std::size_t n = grid.depth_m.size();
        CacheReader reader(bytes);
        std::shared_ptr<CoastField> field(new CoastField());
        field->layerOfWave_ = reader.getVector<int>(waves.waves.size());
        const auto layers = reader.get<std::uint64_t>();
        if (layers > kMaxCoastWaves || field->layerOfWave_.size() != waves.waves.size())
            return nullptr;
        for (std::uint64_t l = 0; l < layers; ++l) {
            field->layers_.push_back(reader.getVector<glm::vec4>(n));
            if (field->layers_.back().size() != n)
                return nullptr;
        }
        field->common_ = reader.getVector<glm::vec4>(n);
        field->reach_.vertical_m = reader.get<double>();
        field->reach_.horizontal_m = reader.get<double>();
        if (!reader.ok() || field->common_.size() != n)
            return nullptr;
        for (const int l : field->layerOfWave_)
            if (l < -1 || l >= int(layers))
                return nullptr;
        field->depth_ = std::move(grid);
        return field;
    }
};

} // namespace detail

namespace coast {

std::shared_ptr<const CoastField> solvedOrCachedField(const WaveSet& waves, DepthGrid grid)
{
    const detail::CacheBytes key = detail::CoastFieldBytes::keyOf(waves, grid, kBreakerIndex);
    if (const auto entry = detail::loadDerived("coast", key.bytes()))
        if (auto field = detail::CoastFieldBytes::fieldOf(entry->payload(), waves, grid))
            return field;
    auto field = std::make_shared<const CoastField>(waves, std::move(grid));
    detail::storeDerived("coast", key.bytes(), detail::CoastFieldBytes::texelsOf(*field).bytes());
    return field;
}

} // namespace coast

} // namespace swell
