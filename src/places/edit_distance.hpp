// How many typing slips apart two names are: insertions, deletions, substitutions and swaps of
// two neighbouring letters ("Zoin" for "Zion") each count one (optimal string alignment).
#pragma once

#include <cstddef>
#include <string_view>

namespace globe::places {

// The distance when it is at most `limit`, else limit + 1 (found without the whole table: the
// names compared are a query and each of the gazetteer's hundreds of thousands of keys).
size_t editDistanceWithin(std::string_view a, std::string_view b, size_t limit);
// Slips allowed for a query of this many characters: none below 4, one up to 7, then two.
size_t typosAllowed(size_t queryLength);

}  // namespace globe::places
