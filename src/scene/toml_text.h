// Steps 1 and 2 of reading a TOML file the user wrote (a scene, a sweep):
// its text checked for size-independent structure (scene/text_scan.h), then
// parsed, a syntax error reported where the mistake is (an array without
// its ']', a string without its closing quote), not where the parser noticed.
#pragma once

#include "scene/places.h"

#include <toml++/toml.h>

#include <string_view>

namespace swell::detail::scenefile {

// Throws InputError at `places.path()`, line and column.
toml::table parseTomlText(std::string_view text, const Places& places);

} // namespace swell::detail::scenefile
