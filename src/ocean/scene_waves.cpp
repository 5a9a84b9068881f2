// The step from a scene's sea and waves to the wave set the Gerstner model
// sums (swell/scene/scene.h): the listed waves, or those the wind raises
// (swell/scene/spectrum.h), in the sea's depth.
#include "swell/scene/scene.h"
#include "swell/scene/spectrum.h"

namespace swell {

WaveSet resolveWaves(const Scene& scene)
{
    if (!scene.sea.wind) {
        WaveSet listed;
        listed.waves = scene.waves.listed;
        listed.depth_m = scene.sea.depth_m;
        return listed;
    }
    // The depth is the sea's, whichever way the waves are made.
    WindSettings wind = *scene.sea.wind;
    wind.depth_m = scene.sea.depth_m;
    return generateWaves(wind);
}

} // namespace swell
