#include "apps/globe/did_you_mean.hpp"

#include <algorithm>

namespace globe::app {

size_t editDistance(std::string_view a, std::string_view b) {
  // Optimal string alignment: three rows (the previous two and this one).
  std::vector<size_t> before(b.size() + 1), previous(b.size() + 1), current(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) previous[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        current[j] = std::min(current[j], before[j - 2] + 1);
      }
    }
    before.swap(previous);
    previous.swap(current);
  }
  return previous[b.size()];
}

std::optional<std::string> closestWord(std::string_view word,
                                       const std::vector<std::string>& candidates) {
  const size_t allowed = std::clamp<size_t>(word.size() / 3, 1, 3);
  std::optional<std::string> best;
  size_t bestDistance = allowed + 1;
  bool tie = false;
  for (const std::string& candidate : candidates) {
    const size_t d = editDistance(word, candidate);
    if (d < bestDistance) {
      best = candidate;
      bestDistance = d;
      tie = false;
    } else if (d == bestDistance && best && *best != candidate) {
      tie = true;
    }
  }
  if (tie || bestDistance == 0) return std::nullopt;
  return best;
}

}  // namespace globe::app
