// Suggestions for misspelt keys and choices (suggestions.h).
#include "scene/suggestions.h"

#include <algorithm>

namespace swell::detail::scenefile {

namespace {

// Edit distance with adjacent transpositions, so "strat" is one step from "start".
std::size_t editDistance(std::string_view a, std::string_view b)
{
    std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
    for (std::size_t i = 0; i <= a.size(); ++i)
        d[i][0] = i;
    for (std::size_t j = 0; j <= b.size(); ++j)
        d[0][j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i)
        for (std::size_t j = 1; j <= b.size(); ++j) {
            std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    return d[a.size()][b.size()];
}

} // namespace

// The candidate closest to `word`, if it is close enough to be a typo.
// The distance is at least the difference in length, so a candidate whose
// length differs by the threshold or more is skipped unmeasured: the table
// editDistance builds is then at most (candidate + 3)^2 entries, whatever
// the word's length (a 4 MiB key once cost 1.1 GB and 31 s here).
std::optional<std::string> closest(std::string_view word, const std::vector<std::string>& candidates)
{
    std::optional<std::string> best;
    std::size_t bestDistance = word.size() >= 5 ? 3 : 2; // must beat this
    for (const std::string& c : candidates) {
        const std::size_t lengthGap = word.size() > c.size() ? word.size() - c.size() : c.size() - word.size();
        if (lengthGap >= bestDistance)
            continue;
        std::size_t d = editDistance(word, c);
        if (d < bestDistance) {
            bestDistance = d;
            best = c;
        }
    }
    return best;
}

} // namespace swell::detail::scenefile
