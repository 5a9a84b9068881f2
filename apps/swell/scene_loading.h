// Loading the scene a command names, or the built-in default.
#pragma once

#include "swell/scene/scene.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace swell::app {

// The scene file a command's SCENE argument names. A path that exists (even
// as a dangling link), or that has a folder in it, is taken as it is, for
// the scene reader to read or refuse; otherwise a preset of that name in `presets` (the
// installed share/swell/scenes, or the source tree's scenes/): "storm" and
// "storm.toml" both name presets/storm.toml. Empty stays empty (the default
// scene). Throws swell::InputError naming the argument and listing the
// presets when neither exists.
std::string resolveScenePath(const std::string& argument, const std::filesystem::path& presets);

// Throws swell::InputError for a bad scene file.
Scene loadSceneOrDefault(const std::string& path);

} // namespace swell::app
