#include "scene_loading.h"

#include "swell/scene_file.h"

namespace swell::app {

Scene loadSceneOrDefault(const std::string& path)
{
    return path.empty() ? defaultScene() : loadScene(path);
}

} // namespace swell::app
