// Step 1 of reading a scene: the text before the TOML parser sees it.
#pragma once

#include "swell/error.h"

#include <optional>
#include <string>
#include <string_view>

namespace swell::detail::scenefile {

// Checks that `text` is UTF-8 without NUL bytes, and that its keys, headers,
// nesting and arrays stay within the structural limits of swell/scene/scene_file.h
// (the TOML parser's recursion and allocation follow them). Throws InputError
// at `path`, line and column of the first problem; broken TOML syntax is left
// for the parser.
void scanSceneText(std::string_view text, const std::string& path);

// A missing ']' at the end of an array's line is found by the TOML parser
// only on the next line, which it reads as more of the array. When the
// parser's error at `errorLine`:`errorColumn` lies on a later line than the
// innermost array still open there, this is the place to report instead:
// the end of the line that opened that array. Strings and comments are
// skipped; nullopt when no array is open.
std::optional<SourcePlace> unclosedArrayBefore(std::string_view text, int errorLine, int errorColumn,
                                               const std::string& path);

// A one-line string whose closing quote is missing runs into the end of its
// line, which the TOML parser reports as a control character inside the
// string. When line `errorLine` ends inside a basic ("...") or literal
// ('...') string, this is the place of that string's opening quote, and
// the quote itself; nullopt otherwise. Comments and closed strings before
// it on the line are skipped; multi-line strings are not looked into.
struct OpenString {
    SourcePlace opening;
    char quote;
};
std::optional<OpenString> unclosedStringOn(std::string_view text, int errorLine, const std::string& path);

} // namespace swell::detail::scenefile
