// "Did you mean": the known word closest to a mistyped one (an option, a subcommand), by edit
// distance, when it is close enough to be what was meant.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace globe::app {

// Levenshtein distance, with a swap of two neighbouring letters counting one (--camrea).
size_t editDistance(std::string_view a, std::string_view b);

// The candidate nearest to `word`, when within a third of its length (at least 1, at most 3
// edits); nullopt otherwise or when two candidates are equally near.
std::optional<std::string> closestWord(std::string_view word,
                                       const std::vector<std::string>& candidates);

}  // namespace globe::app
