// "Did you mean ...?" suggestions for unknown keys and values (docs/maths.md [D4]).
#pragma once
#include <optional>
#include <string>
#include <vector>

namespace hinf {

// Optimal-string-alignment distance (Levenshtein plus adjacent transpositions),
// compared case-insensitively.
int edit_distance(const std::string& a, const std::string& b);

// The candidate closest to `word`, if it is close enough to be a plausible typo:
// distance <= max(2, |word| / 3), ties to the first candidate in order; failing that,
// the first candidate that is a prefix of `word` or has `word` as a prefix (>= 3 chars).
std::optional<std::string> closest_match(const std::string& word,
                                         const std::vector<std::string>& candidates);

}  // namespace hinf
