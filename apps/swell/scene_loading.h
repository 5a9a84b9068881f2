// Loading the scene a command names, or the built-in default.
#pragma once

#include "swell/scene.h"

#include <string>

namespace swell::app {

// Throws swell::InputError for a bad scene file.
Scene loadSceneOrDefault(const std::string& path);

} // namespace swell::app
