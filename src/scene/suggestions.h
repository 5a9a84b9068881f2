// "Did you mean": the known name closest to a misspelt one.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace swell::detail::scenefile {

// The candidate closest to `word` by edit distance (with adjacent
// transpositions), if it is close enough to be a typo: 1 edit for words under
// 5 characters, 2 for longer ones. The work is bounded by the candidates'
// lengths, whatever the length of `word`.
std::optional<std::string> closest(std::string_view word, const std::vector<std::string>& candidates);

} // namespace swell::detail::scenefile
