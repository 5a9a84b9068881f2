// The empty stage the golden tests build on: the default scene without
// waves, island or objects, with fog pushed far out of view, and without
// anti-aliasing, so that a test's pixels are those of the effect it checks
// (tests/golden/test_antialiasing.cpp checks the anti-aliasing).
#pragma once

#include "swell/scene/scene.h"

namespace swell::test {

inline Scene emptyStage()
{
    Scene scene = defaultScene();
    scene.sea.wind.reset();
    scene.waves.listed.clear();
    scene.showTerrain = false;
    scene.objects.clear();
    scene.fog.start_m = 1.0e5;
    scene.fog.end_m = 2.0e5;
    scene.antialiasing = Antialiasing::Off;
    return scene;
}

} // namespace swell::test
