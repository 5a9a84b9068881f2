// Scenes tests start from: the default scene's sea with nothing else in it.
#pragma once

#include "swell/scene/scene.h"

namespace swell::test {

// The default scene without its island and objects.
inline Scene openSea()
{
    Scene scene = defaultScene();
    scene.objects.clear();
    scene.showTerrain = false;
    return scene;
}

// The same sea as the spectral model under a 20 m/s wind (the storm's).
inline Scene openSpectralStorm()
{
    Scene scene = openSea();
    scene.waves.model = WaveModelKind::Spectral;
    scene.sea.wind->windSpeed_mps = 20.0;
    return scene;
}

// The open sea seen through a strong lens with a tangential part (k1 -0.22,
// k2 0.05, p1 0.002, p2 -0.001): the label tests' lens.
inline Scene openSeaThroughALens()
{
    Scene scene = openSea();
    scene.camera.distortionK1 = -0.22;
    scene.camera.distortionK2 = 0.05;
    scene.camera.distortionP1 = 0.002;
    scene.camera.distortionP2 = -0.001;
    return scene;
}

} // namespace swell::test
