#include "places/edit_distance.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <vector>

namespace globe::places {
namespace {

// Which letters and digits a name holds (anything else one bit).
uint64_t letterSet(std::string_view text) {
  uint64_t set = 0;
  for (const char c : text) {
    const int bit = c >= 'a' && c <= 'z'   ? c - 'a'
                    : c >= '0' && c <= '9' ? 26 + (c - '0')
                                           : 36 + (static_cast<unsigned char>(c) % 27);
    set |= uint64_t{1} << bit;
  }
  return set;
}

}  // namespace

size_t editDistanceWithin(std::string_view a, std::string_view b, size_t limit) {
  const size_t over = limit + 1;
  if ((a.size() > b.size() ? a.size() - b.size() : b.size() - a.size()) > limit) return over;
  // Each slip adds or removes at most two letters from the set of letters a name holds (a swap
  // none), so names whose sets differ by more than 2 × limit are further apart: most of the
  // gazetteer's keys are ruled out here, without the table.
  if (static_cast<size_t>(std::popcount(letterSet(a) ^ letterSet(b))) > 2 * limit) return over;
  // Three rows of the table (the one before last for swaps), kept between calls.
  thread_local std::array<std::vector<size_t>, 3> rows;
  for (auto& row : rows) row.assign(b.size() + 1, 0);
  for (size_t j = 0; j <= b.size(); ++j) rows[1][j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    std::vector<size_t>& row = rows[(i + 1) % 3];
    const std::vector<size_t>& up = rows[i % 3];
    const std::vector<size_t>& upUp = rows[(i + 2) % 3];
    row[0] = i;
    size_t rowBest = row[0];
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      size_t d = std::min({up[j] + 1, row[j - 1] + 1, up[j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d = std::min(d, upUp[j - 2] + 1);
      row[j] = d;
      rowBest = std::min(rowBest, d);
    }
    if (rowBest > limit) return over;  // every later row is at least this
  }
  return std::min(rows[(a.size() + 1) % 3][b.size()], over);
}

size_t typosAllowed(size_t queryLength) {
  if (queryLength < 4) return 0;
  return queryLength < 8 ? 1 : 2;
}

}  // namespace globe::places
