// Steps 1 and 2 of reading a scene file (see scene_file.cpp), shared with
// sweep files: the text's structure, then TOML syntax, with the parser's
// messages turned into what went wrong where the user made the mistake.
#include "scene/toml_text.h"

#include "scene/text_scan.h"

#include <fmt/format.h>

namespace swell::detail::scenefile {

toml::table parseTomlText(std::string_view text, const Places& places)
{
    scanSceneText(text, places.path());
    toml::table root;
    try {
        root = toml::parse(text, std::string_view(places.path()));
    } catch (const toml::parse_error& e) {
        const bool arrayOpen = e.description().find("closing ']'") != std::string_view::npos;
        if (const std::optional<SourcePlace> open =
                arrayOpen ? unclosedArrayBefore(text, int(e.source().begin.line),
                                                                  int(e.source().begin.column), places.path())
                          : std::nullopt)
            fail(*open, fmt::format("TOML syntax: this array has no closing ']' (the parser read on into line {} "
                                    "and stopped there: {})",
                                    e.source().begin.line, e.description()));
        // A string that runs into the end of its line: its closing quote is
        // missing (the parser calls the line break a control character).
        const bool controlInString = e.description().find("control character") != std::string_view::npos;
        if (const std::optional<OpenString> string =
                controlInString ? unclosedStringOn(text, int(e.source().begin.line), places.path()) : std::nullopt)
            fail(string->opening, fmt::format("TOML syntax: this string has no closing {0} before the end of its line "
                                              "(a {0}...{0} string ends on the line it starts; write {0}{0}{0} for one "
                                              "that spans lines)",
                                              string->quote));
        fail(places.of(e.source()), fmt::format("TOML syntax: {}", e.description()));
    }
    return root;
}

} // namespace swell::detail::scenefile
