// Step 3 of reading a scene: the parsed TOML tree into a Scene, key by key.
#pragma once

#include "scene/places.h"
#include "swell/scene/scene.h"

#include <toml++/toml.h>

namespace swell::detail::scenefile {

// Reads `root` into a Scene: every key known (else an unknown-key error with
// a suggestion), every value of the right type and in range (the parameter
// table, swell/scene/parameters.h), every list within its limit. Records where
// each key was in `places`. Throws InputError at the first problem.
Scene readScene(const toml::table& root, Places& places);

} // namespace swell::detail::scenefile
