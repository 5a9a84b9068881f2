// The empty stage the golden tests build on: the default scene without
// waves, island or objects, and with fog pushed far out of view.
#pragma once

#include "swell/scene.h"

namespace swell::test {

inline Scene emptyStage()
{
    Scene scene = defaultScene();
    scene.waves.wind.reset();
    scene.waves.listed.waves.clear();
    scene.showTerrain = false;
    scene.objects.clear();
    scene.fog.start_m = 1.0e5;
    scene.fog.end_m = 2.0e5;
    return scene;
}

} // namespace swell::test
