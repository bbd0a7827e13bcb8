// The other ways a folded query may be written (name_fold.hpp): abbreviations people type for
// the words in names ("Mt Fuji" for "Mount Fuji", "St Louis" for "Saint Louis" and back, "N" for
// "North") and German transliterations ("Zuerich" for "Zürich", whose key is "zurich"). The
// gazetteer matches each form as if the user had typed it.
#pragma once

#include <string>
#include <vector>

namespace globe::places {

// The query itself first, then its other forms; at most kMaxQueryForms, no repeats.
std::vector<std::string> queryForms(const std::string& foldedQuery);
inline constexpr size_t kMaxQueryForms = 16;

}  // namespace globe::places
