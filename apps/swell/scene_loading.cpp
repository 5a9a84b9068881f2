#include "scene_loading.h"

#include "swell/scene_file.h"

#include <cstdio>

namespace swell::app {

Scene loadSceneOrDefault(const std::string& path)
{
    Scene scene = path.empty() ? defaultScene() : loadScene(path);
    // Waves whose crests would loop over themselves are made gentler when
    // rendered; say so, naming the waves, rather than change them silently.
    WaveSet waves = resolveWaves(scene.waves);
    if (const std::string warning = limitSteepness(waves); !warning.empty())
        std::fprintf(stderr, "swell: warning: %s: %s\n", path.empty() ? "default scene" : path.c_str(), warning.c_str());
    return scene;
}

} // namespace swell::app
