// The built-in scene (the step from its waves to the wave set the renderer
// sums, resolveWaves(), is the ocean's: ocean/scene_waves.cpp).
#include "swell/scene/scene.h"

namespace swell {

Scene defaultScene()
{
    // Everything not set here keeps the member defaults of scene.h, which are
    // also what a scene file gets for a key it leaves out.
    Scene scene;

    // A moderate breeze that has blown across open ocean for a day: waves a
    // few tens of metres long running away from the camera, roughly towards
    // the low sun in front-left (SunSettings' default), which lays a glitter
    // path across their faces.
    WindSettings wind;
    wind.windSpeed_mps = 8.0;
    wind.windDirection_deg = 250.0; // towards -z, a little towards -x
    wind.spread_deg = 35.0;
    wind.fetch_km = 300.0;
    wind.waveCount = 32;
    wind.minWavelength_m = 0.5;
    wind.seed = 1;
    wind.steepness = 0.6;
    scene.sea.wind = wind;

    // A buoy riding the swell in the foreground and a rock further out,
    // both in view of the default camera (6 m up, looking along -z).
    SceneObject buoy;
    buoy.path = "builtin:buoy";
    buoy.position_m = {6.0, 0.0, -35.0};
    buoy.floats = true;
    scene.objects.push_back(buoy);

    SceneObject rock;
    rock.path = "builtin:rock";
    rock.position_m = {-45.0, 0.0, -140.0};
    rock.yaw_deg = 30.0;
    rock.scale = 4.0;
    scene.objects.push_back(rock);

    scene.showTerrain = true;
    return scene;
}

} // namespace swell
