// The scene file's text values (text_values.h).
#include "scene/text_values.h"

#include <fmt/format.h>

#include <algorithm>

namespace swell::detail::scenefile {

namespace {

// A string (`what` says what it holds, for the message when it is not one),
// non-empty (`whenEmpty` says what to give instead) and without control
// characters.
std::string readText(const toml::node& node, const std::string& shown, const Places& places, std::string_view what,
                     std::string_view whenEmpty)
{
    const auto* s = node.as_string();
    if (s == nullptr)
        fail(places.of(node.source()), fmt::format("{} must be a string ({}), not {}", shown, what, typeName(node)));
    if (s->get().empty())
        fail(places.of(node.source()), fmt::format("{} is empty; {}", shown, whenEmpty));
    if (hasControlCharacter(s->get()))
        fail(places.of(node.source()), fmt::format("{} contains a control character", shown));
    return s->get();
}

} // namespace

std::string readPath(const toml::node& node, const std::string& shown, const Places& places)
{
    return readText(node, shown, places, "a file path", "it must name a file");
}

std::string readNodeName(const toml::node& node, const std::string& shown, const Places& places)
{
    return readText(node, shown, places, "a glTF node's name", "it must name a node of the model");
}

std::string readClass(const toml::node& node, const std::string& shown, const Places& places)
{
    return readText(node, shown, places, "the object's class in the labels",
                    "give the object's class (\"sailing_yacht\"), or leave the key out for its model's name");
}

std::string readRigName(const toml::node& node, const std::string& shown, const Places& places)
{
    const auto* s = node.as_string();
    if (s == nullptr)
        fail(places.of(node.source()),
             fmt::format("{} must be a string (the camera's name), not {}", shown, typeName(node)));
    const std::string& name = s->get();
    const bool allowed = std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
    });
    if (name.empty() || name.size() > 32 || !allowed)
        fail(places.of(node.source()),
             fmt::format("{} = \"{}\": a rig camera's name is part of its files' names: 1 to 32 letters, digits, "
                         "'_' or '-'",
                         shown, shortText(name)));
    return name;
}

} // namespace swell::detail::scenefile
