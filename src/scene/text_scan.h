// Step 1 of reading a scene: the text before the TOML parser sees it.
#pragma once

#include <string>
#include <string_view>

namespace swell::detail::scenefile {

// Checks that `text` is UTF-8 without NUL bytes, and that its keys, headers,
// nesting and arrays stay within the structural limits of swell/scene_file.h
// (the TOML parser's recursion and allocation follow them). Throws InputError
// at `path`, line and column of the first problem; broken TOML syntax is left
// for the parser.
void scanSceneText(std::string_view text, const std::string& path);

} // namespace swell::detail::scenefile
