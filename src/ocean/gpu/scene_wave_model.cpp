// The wave model a scene asks for.
#include "ocean/coast/coast_grid.h"

#include "swell/coast_field.h"
#include "swell/error.h"
#include "swell/gerstner_model.h"
#include "swell/scene/scene.h"
#include "swell/scene/seabed.h"
#include "swell/spectral_model.h"

#include <deque>
#include <mutex>

namespace swell {

namespace {

bool sameWaves(const WaveSet& a, const WaveSet& b) { return a.waves == b.waves && a.depth_m == b.depth_m; }

bool sameGrid(const DepthGrid& a, const DepthGrid& b)
{
    return a.origin_m == b.origin_m && a.cell_m == b.cell_m && a.size == b.size && a.outsideDepth_m == b.outsideDepth_m
           && a.depth_m == b.depth_m;
}

// The field the same waves over the same floor gave last: a scene's
// parameters mostly change neither (the sun, the camera, the grid), and a
// field over the built-in island takes about half a second to solve. The
// last few are kept, process-wide.
std::shared_ptr<const CoastField> coastFieldOf(const WaveSet& waves, DepthGrid grid)
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
    auto field = std::make_shared<const CoastField>(waves, std::move(grid));
    const std::lock_guard lock(mutex);
    kept.push_front({waves, field});
    if (kept.size() > kKept)
        kept.pop_back();
    return field;
}

} // namespace

std::unique_ptr<WaveModel> makeWaveModel(const Scene& scene)
{
    if (scene.waves.model == WaveModelKind::Spectral)
        return makeWaveModel(scene, Seabed());
    return makeWaveModel(scene, Seabed(scene));
}

std::unique_ptr<WaveModel> makeWaveModel(const Scene& scene, const Seabed& seabed)
{
    if (scene.waves.model == WaveModelKind::Spectral) {
        if (!scene.sea.wind)
            throw InputError({}, "waves.model = \"spectral\" needs the wind: add a [waves.wind] table");
        SpectralSettings settings;
        settings.wind = *scene.sea.wind;
        // The water depth is the scene's, as for generated Gerstner waves.
        settings.wind.depth_m = scene.sea.depth_m;
        settings.choppiness = scene.waves.choppiness;
        settings.foamLifetime_s = scene.waves.foamLifetime_s;
        settings.historyStart_s = scene.historyStart_s;
        settings.seed = scene.sea.wind->seed;
        return std::make_unique<SpectralModel>(settings);
    }
    WaveSet waves = resolveWaves(scene);
    limitSteepness(waves);
    if (std::optional<DepthGrid> grid = coast::depthGridOf(seabed, waves))
        waves.coast = coastFieldOf(waves, std::move(*grid));
    return std::make_unique<GerstnerModel>(std::move(waves));
}

} // namespace swell
