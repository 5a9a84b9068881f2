// sceneChanges(): walks the parameter table, so a parameter's declared effect
// is the only thing that says what its change costs.
#include "swell/scene/scene_changes.h"

#include <algorithm>

namespace swell {

ParameterEffect sceneChanges(const Scene& before, const Scene& after)
{
    ParameterEffect effects = ParameterEffect::Frame;
    // The shape of the scene, which no parameter holds.
    if (before.sea.wind.has_value() != after.sea.wind.has_value() ||
        before.waves.listed.size() != after.waves.listed.size())
        effects |= ParameterEffect::Waves;
    const bool sameObjectFiles = std::equal(
        before.objects.begin(), before.objects.end(), after.objects.begin(), after.objects.end(),
        [](const SceneObject& a, const SceneObject& b) { return a.path == b.path && a.hullNode == b.hullNode; });
    if (!sameObjectFiles || before.sky.cubemapFaces != after.sky.cubemapFaces ||
        before.assetFolder != after.assetFolder)
        effects |= ParameterEffect::World;
    const SeabedSettings &floorBefore = before.seabed, &floorAfter = after.seabed;
    if (floorBefore.beaches.size() != floorAfter.beaches.size() || floorBefore.shelves.size() != floorAfter.shelves.size()
        || floorBefore.breakwaters.size() != floorAfter.breakwaters.size()
        || floorBefore.heightmap.path != floorAfter.heightmap.path || before.assetFolder != after.assetFolder)
        effects |= ParameterEffect::Seabed;

    for (const Parameter& p : parameters()) {
        if (p.effect == ParameterEffect::Frame || hasEffect(effects, p.effect))
            continue; // nothing more this parameter could add
        if (isPresent(p, before) != isPresent(p, after)) {
            effects |= p.effect;
            continue;
        }
        if (!isPresent(p, after))
            continue;
        const std::size_t items = std::min(listSize(before, p.list), listSize(after, p.list));
        for (std::size_t i = 0; i < items; ++i)
            if (p.get(before, i) != p.get(after, i)) {
                effects |= p.effect;
                break;
            }
    }
    return effects;
}

} // namespace swell
