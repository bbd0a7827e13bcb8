// Greedy word wrap: each line takes as many words as fit (the usual, not Knuth–Plass, which
// would need the whole paragraph's costs and buys little in a small info box).
#include "text/text_wrap.hpp"

#include <algorithm>
#include <cmath>

namespace globe::text {
namespace {

// The byte length of the UTF-8 character starting at text[at] (1 for a stray byte).
size_t utf8CharBytes(std::string_view text, size_t at) {
  size_t end = at + 1;
  while (end < text.size() && (static_cast<unsigned char>(text[end]) & 0xC0U) == 0x80U) ++end;
  return end - at;
}

// Appends one '\n'-free piece's lines.
void wrapPiece(std::string_view piece, float maxWidthPixels, const TextWidth& widthOf,
               std::vector<std::string>& lines) {
  std::string line;
  size_t at = 0;
  bool any = false;
  while (at < piece.size()) {
    if (piece[at] == ' ') {
      ++at;
      continue;
    }
    const size_t end = std::min(piece.find(' ', at), piece.size());
    std::string_view word = piece.substr(at, end - at);
    at = end;
    const std::string joined = line.empty() ? std::string(word) : line + " " + std::string(word);
    if (widthOf(joined) <= maxWidthPixels) {
      line = joined;
      continue;
    }
    if (!line.empty()) {
      lines.push_back(std::move(line));
      any = true;
      line.clear();
    }
    // The word alone: broken between characters while it is wider than a line.
    while (!word.empty() && widthOf(word) > maxWidthPixels) {
      size_t cut = utf8CharBytes(word, 0);
      for (size_t next = cut; next < word.size(); next += utf8CharBytes(word, next)) {
        if (widthOf(word.substr(0, next)) > maxWidthPixels) break;
        cut = next;
      }
      lines.emplace_back(word.substr(0, cut));
      any = true;
      word.remove_prefix(cut);
    }
    line = std::string(word);
  }
  if (!line.empty() || !any) lines.push_back(std::move(line));
}

}  // namespace

std::vector<std::string> wrapText(std::string_view paragraph, float maxWidthPixels,
                                  const TextWidth& widthOf) {
  std::vector<std::string> lines;
  const bool unlimited = !std::isfinite(maxWidthPixels) || maxWidthPixels <= 0.0f;
  size_t start = 0;
  while (true) {
    const size_t newline = paragraph.find('\n', start);
    const std::string_view piece = paragraph.substr(
        start, newline == std::string_view::npos ? std::string_view::npos : newline - start);
    if (unlimited) {
      lines.emplace_back(piece);
    } else {
      wrapPiece(piece, maxWidthPixels, widthOf, lines);
    }
    if (newline == std::string_view::npos) break;
    start = newline + 1;
  }
  return lines;
}

}  // namespace globe::text
