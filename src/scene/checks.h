// Step 4 of reading a scene: the scene as a whole. Also what validateScene
// runs, for scenes built in code.
#pragma once

#include "scene/places.h"
#include "swell/scene/parameters.h"
#include "swell/scene/scene.h"

#include <filesystem>

namespace swell::detail::scenefile {

// Checks every parameter's range, the cross-field rules, the files the
// scene names (inside `base`, the scene file's folder, regular and readable)
// and the wave set. Throws InputError at the key's place in `places`.
// `scope` leaves out the costly checks a change cannot affect: the files
// unless it has ParameterEffect::World (the heightmap's: World or Seabed),
// the waves unless ParameterEffect::Waves.
void checkScene(const Scene& scene, const Places& places, const std::filesystem::path& base,
                ParameterEffect scope = ParameterEffect::World | ParameterEffect::Waves);

// The folder relative paths in `sceneFile` start at: its folder, or "." when it has none.
std::filesystem::path baseFolder(const std::filesystem::path& sceneFile);

} // namespace swell::detail::scenefile
