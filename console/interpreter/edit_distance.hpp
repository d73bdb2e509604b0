#pragma once
// Levenshtein distance, for "did you mean" suggestions.
#include <string>
#include <string_view>
#include <vector>

namespace stride::console {

std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidate closest to `word`, or "" if none is within max(2, |word|/3) edits.
std::string nearest(std::string_view word, const std::vector<std::string>& candidates);

}  // namespace stride::console
