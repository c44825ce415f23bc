// "Did you mean ...?": the valid name nearest to a misspelt one, for scene error notes.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace glint {

// Optimal-string-alignment (restricted Damerau-Levenshtein) distance, ignoring ASCII case:
// insertions, deletions, substitutions and swaps of neighbours each cost 1.
int edit_distance(std::string_view a, std::string_view b);

// The candidate nearest to `name`, if one is near enough to be a plausible typo: at most a third
// of the longer name's length in edits (at least one). Ties go to the earlier candidate.
std::optional<std::string> suggest_name(std::string_view name,
                                        std::span<const std::string_view> candidates);

// " (did you mean \"x\"?)" when suggest_name finds x, else the empty string; meant to be
// appended to a note that lists the candidates.
std::string did_you_mean(std::string_view name, std::span<const std::string_view> candidates);

}  // namespace glint
