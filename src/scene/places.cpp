// Places and message helpers (places.h).
#include "scene/places.h"

#include <fmt/format.h>

#include <algorithm>

namespace swell::detail::scenefile {

std::string parentKey(std::string_view key)
{
    if (!key.empty() && key.back() == ']') {
        auto open = key.rfind('[');
        return std::string(key.substr(0, open == std::string_view::npos ? 0 : open));
    }
    auto dot = key.rfind('.');
    return dot == std::string_view::npos ? std::string() : std::string(key.substr(0, dot));
}

std::string shortText(std::string_view s)
{
    constexpr std::size_t kMaxQuoted = 80;
    return s.size() <= kMaxQuoted ? std::string(s) : fmt::format("{}... ({} bytes)", s.substr(0, kMaxQuoted), s.size());
}

bool hasControlCharacter(std::string_view s)
{
    return std::any_of(s.begin(), s.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; });
}

std::string join(std::string_view prefix, std::string_view key)
{
    return prefix.empty() ? std::string(key) : fmt::format("{}.{}", prefix, key);
}

} // namespace swell::detail::scenefile
