// The wave model a scene asks for.
#include "swell/gerstner_model.h"
#include "swell/scene.h"

namespace swell {

std::unique_ptr<WaveModel> makeWaveModel(const Scene& scene)
{
    WaveSet waves = resolveWaves(scene.waves);
    limitSteepness(waves);
    return std::make_unique<GerstnerModel>(std::move(waves));
}

} // namespace swell
