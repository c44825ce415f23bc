// Edit distance and name suggestions for "did you mean" notes.
#include "glint/scene/suggest.h"

#include <algorithm>
#include <cstdlib>
#include <vector>

namespace glint {

namespace {
char lower(char c) { return (c >= 'A' && c <= 'Z') ? char(c - 'A' + 'a') : c; }
}  // namespace

int edit_distance(std::string_view a, std::string_view b) {
    // Three rolling rows of the dynamic-programming table: the swap rule looks two rows back.
    const std::size_t n = b.size();
    std::vector<int> before(n + 1), previous(n + 1), current(n + 1);
    for (std::size_t j = 0; j <= n; ++j) previous[j] = int(j);
    for (std::size_t i = 1; i <= a.size(); ++i) {
        current[0] = int(i);
        for (std::size_t j = 1; j <= n; ++j) {
            const int cost = lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1;
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + cost});
            if (i > 1 && j > 1 && lower(a[i - 1]) == lower(b[j - 2]) &&
                lower(a[i - 2]) == lower(b[j - 1])) {
                current[j] = std::min(current[j], before[j - 2] + 1);
            }
        }
        std::swap(before, previous);
        std::swap(previous, current);
    }
    return previous[n];
}

std::optional<std::string> suggest_name(std::string_view name,
                                        std::span<const std::string_view> candidates) {
    // Names far longer than any keyword cannot be typos of one; skip the quadratic work.
    if (name.size() > 64) return std::nullopt;
    std::optional<std::string> best;
    int best_distance = 0;
    for (const std::string_view candidate : candidates) {
        const int longer = int(std::max(name.size(), candidate.size()));
        const int limit = std::max(1, longer / 3);
        // The difference in length is a lower bound of the distance: a cheap first cut.
        if (std::abs(int(name.size()) - int(candidate.size())) > limit) continue;
        const int d = edit_distance(name, candidate);
        if (d > limit || d >= longer) continue;
        if (!best || d < best_distance) {
            best = std::string(candidate);
            best_distance = d;
        }
    }
    return best;
}

std::string did_you_mean(std::string_view name, std::span<const std::string_view> candidates) {
    const auto suggestion = suggest_name(name, candidates);
    return suggestion ? " (did you mean \"" + *suggestion + "\"?)" : std::string();
}

}  // namespace glint
