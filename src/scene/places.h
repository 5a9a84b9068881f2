// Where each key of a scene file was, so that later checks can point at it,
// and the small helpers every part of the scene reader reports problems with.
#pragma once

#include "swell/error.h"

#include <toml++/toml.h>

#include <functional>
#include <initializer_list>
#include <map>
#include <string>
#include <string_view>

namespace swell::detail::scenefile {

// The key that encloses `key`: "objects[2]" for "objects[2].scale",
// "objects" for "objects[2]", "" for "fog".
std::string parentKey(std::string_view key);

// Places: where each key of the file was, so that later checks can point at it.
// Keys are written as the user sees them: "fog.end_m", "objects[2].scale",
// "sky.faces[3]"; "" is the file itself.
class Places {
public:
    using Map = std::map<std::string, SourcePlace, std::less<>>;

    explicit Places(std::string path) : path_(std::move(path)) {}
    // Seeded with places known already (Scene::keyPlaces).
    Places(std::string path, Map places) : path_(std::move(path)), places_(std::move(places)) {}

    const std::string& path() const { return path_; }

    SourcePlace of(const toml::source_region& region) const
    {
        return {path_, static_cast<int>(region.begin.line), static_cast<int>(region.begin.column)};
    }

    void add(std::string key, const toml::source_region& region) { places_[std::move(key)] = of(region); }

    bool has(std::string_view key) const { return places_.find(key) != places_.end(); }

    // The place of `key`, else of the nearest enclosing key that has one, else the file.
    SourcePlace at(std::string_view key) const
    {
        std::string k(key);
        while (true) {
            if (auto it = places_.find(k); it != places_.end())
                return it->second;
            if (k.empty())
                return {path_, 0, 0};
            k = parentKey(k);
        }
    }

    // The place of the first of `keys` the file has, else at(first key).
    SourcePlace first(std::initializer_list<std::string_view> keys) const
    {
        for (std::string_view k : keys)
            if (has(k))
                return at(k);
        return at(*keys.begin());
    }

    // Every key's place, for Scene::keyPlaces.
    const Map& all() const { return places_; }

private:
    std::string path_;
    Map places_;
};

// "a table", "an array", "a string", ...: a TOML value's type in a message.
std::string typeName(const toml::node& node);

[[noreturn]] inline void fail(SourcePlace place, const std::string& message)
{
    throw InputError(std::move(place), message);
}

// User text quoted in a message, cut to a readable length: a 4 MiB key
// must not become a 4 MiB message.
std::string shortText(std::string_view s);

bool hasControlCharacter(std::string_view s);

// "prefix.key", or "key" when the prefix is empty.
std::string join(std::string_view prefix, std::string_view key);

} // namespace swell::detail::scenefile
