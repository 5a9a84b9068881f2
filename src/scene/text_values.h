// The scene file's keys whose values are text (reader.cpp): file paths, a
// glTF node's name, an object's class, a rig camera's name. Each throws
// InputError at the value's place (`places`) naming the key as `shown`.
#pragma once

#include "scene/places.h"

#include <toml++/toml.h>

#include <string>

namespace swell::detail::scenefile {

// A file path: a non-empty string without control characters.
std::string readPath(const toml::node& node, const std::string& shown, const Places& places);
// A glTF node's name (objects[i].hull_node): likewise.
std::string readNodeName(const toml::node& node, const std::string& shown, const Places& places);
// An object's class in the labels: likewise (a fixed class's name is
// validateScene()'s, for scenes made in code too).
std::string readClass(const toml::node& node, const std::string& shown, const Places& places);
// A rig camera's name: a part of its files' names (NAME.left.png), so
// letters, digits, '_' and '-' alone, 1 to 32 of them.
std::string readRigName(const toml::node& node, const std::string& shown, const Places& places);

} // namespace swell::detail::scenefile
