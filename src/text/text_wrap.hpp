// Word wrapping for text boxes, from text widths alone (no GL), so it is unit-testable.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace globe::text {

// The width of a piece of UTF-8 text in pixels (FontFace::measure(...).widthPixels).
using TextWidth = std::function<float(std::string_view utf8)>;

// Splits a paragraph into lines no wider than maxWidthPixels, breaking at spaces (runs of spaces
// at a break are dropped) and at '\n'. A word wider than the whole line is broken between UTF-8
// characters (at least one a line). A non-finite or non-positive width: one line per '\n' piece.
std::vector<std::string> wrapText(std::string_view paragraph, float maxWidthPixels,
                                  const TextWidth& widthOf);

}  // namespace globe::text
