// The wave model a scene asks for.
#include "ocean/coast/coast_grid.h"

#include "swell/coast_field.h"
#include "swell/error.h"
#include "swell/gerstner_model.h"
#include "swell/scene/scene.h"
#include "swell/scene/seabed.h"
#include "swell/spectral_model.h"

namespace swell {

std::unique_ptr<WaveModel> makeWaveModel(const Scene& scene) { return makeWaveModel(scene, Seabed(scene)); }

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
        return std::make_unique<SpectralModel>(settings, seabed);
    }
    WaveSet waves = resolveWaves(scene);
    limitSteepness(waves);
    waves.coast = coast::coastFieldOf(seabed, waves);
    return std::make_unique<GerstnerModel>(std::move(waves));
}

} // namespace swell
