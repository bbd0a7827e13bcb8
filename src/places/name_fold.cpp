#include "places/name_fold.hpp"

#include <cstdint>
#include <optional>

namespace globe::places {
namespace {

// ASCII for U+00C0..U+017F (Latin-1 Supplement letters, Latin Extended-A), "" where none.
constexpr const char* kLatin[] = {
    // U+00C0
    "a",
    "a",
    "a",
    "a",
    "a",
    "a",
    "ae",
    "c",
    "e",
    "e",
    "e",
    "e",
    "i",
    "i",
    "i",
    "i",
    // U+00D0
    "d",
    "n",
    "o",
    "o",
    "o",
    "o",
    "o",
    "",
    "o",
    "u",
    "u",
    "u",
    "u",
    "y",
    "th",
    "ss",
    // U+00E0
    "a",
    "a",
    "a",
    "a",
    "a",
    "a",
    "ae",
    "c",
    "e",
    "e",
    "e",
    "e",
    "i",
    "i",
    "i",
    "i",
    // U+00F0
    "d",
    "n",
    "o",
    "o",
    "o",
    "o",
    "o",
    "",
    "o",
    "u",
    "u",
    "u",
    "u",
    "y",
    "th",
    "y",
    // U+0100
    "a",
    "a",
    "a",
    "a",
    "a",
    "a",
    "c",
    "c",
    "c",
    "c",
    "c",
    "c",
    "c",
    "c",
    "d",
    "d",
    // U+0110
    "d",
    "d",
    "e",
    "e",
    "e",
    "e",
    "e",
    "e",
    "e",
    "e",
    "e",
    "e",
    "g",
    "g",
    "g",
    "g",
    // U+0120
    "g",
    "g",
    "g",
    "g",
    "h",
    "h",
    "h",
    "h",
    "i",
    "i",
    "i",
    "i",
    "i",
    "i",
    "i",
    "i",
    // U+0130
    "i",
    "i",
    "ij",
    "ij",
    "j",
    "j",
    "k",
    "k",
    "k",
    "l",
    "l",
    "l",
    "l",
    "l",
    "l",
    "l",
    // U+0140
    "l",
    "l",
    "l",
    "n",
    "n",
    "n",
    "n",
    "n",
    "n",
    "n",
    "n",
    "n",
    "o",
    "o",
    "o",
    "o",
    // U+0150
    "o",
    "o",
    "oe",
    "oe",
    "r",
    "r",
    "r",
    "r",
    "r",
    "r",
    "s",
    "s",
    "s",
    "s",
    "s",
    "s",
    // U+0160
    "s",
    "s",
    "t",
    "t",
    "t",
    "t",
    "t",
    "t",
    "u",
    "u",
    "u",
    "u",
    "u",
    "u",
    "u",
    "u",
    // U+0170
    "u",
    "u",
    "u",
    "u",
    "w",
    "w",
    "y",
    "y",
    "y",
    "z",
    "z",
    "z",
    "z",
    "z",
    "z",
    "s",
};

// The code point at utf8[i], i moved past it; nullopt for a malformed sequence (i moved one byte).
std::optional<uint32_t> nextCodePoint(std::string_view utf8, size_t& i) {
  const auto c = static_cast<unsigned char>(utf8[i]);
  if (c < 0x80) {
    ++i;
    return c;
  }
  const size_t length = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : c >= 0xC0 ? 2 : 1;
  uint32_t code = length == 2 ? c & 0x1FU : length == 3 ? c & 0x0FU : c & 0x07U;
  bool good = length > 1 && i + length <= utf8.size();
  for (size_t k = 1; good && k < length; ++k) {
    const auto next = static_cast<unsigned char>(utf8[i + k]);
    good = (next & 0xC0U) == 0x80U;
    code = (code << 6) | (next & 0x3FU);
  }
  i += good ? length : 1;
  return good ? std::optional<uint32_t>(code) : std::nullopt;
}

bool isLatin(uint32_t code) { return code >= 0xC0 && code <= 0x17F; }
bool isCombiningAccent(uint32_t code) { return code >= 0x300 && code <= 0x36F; }

}  // namespace

std::string foldName(std::string_view utf8) {
  std::string out;
  bool space = false;
  const auto emit = [&](std::string_view piece) {
    if (piece.empty()) {
      space = !out.empty();
      return;
    }
    if (space) out.push_back(' ');
    space = false;
    out.append(piece);
  };
  for (size_t i = 0; i < utf8.size();) {
    const std::optional<uint32_t> code = nextCodePoint(utf8, i);
    if (code && ((*code >= 'a' && *code <= 'z') || (*code >= '0' && *code <= '9'))) {
      const char same = static_cast<char>(*code);
      emit(std::string_view(&same, 1));
    } else if (code && *code >= 'A' && *code <= 'Z') {
      const char lower = static_cast<char>(*code - 'A' + 'a');
      emit(std::string_view(&lower, 1));
    } else if (code && isLatin(*code)) {
      emit(kLatin[*code - 0xC0]);
    } else if (!code || !isCombiningAccent(*code)) {  // a combining accent is dropped
      emit("");
    }
  }
  return out;
}

std::string asciiForDisplay(std::string_view utf8) {
  std::string out;
  for (size_t i = 0; i < utf8.size();) {
    const std::optional<uint32_t> code = nextCodePoint(utf8, i);
    if (code && *code < 0x80) {
      out.push_back(*code >= 0x20 && *code < 0x7F ? static_cast<char>(*code) : '?');
      continue;
    }
    if (code && isCombiningAccent(*code)) continue;  // dropped
    std::string piece = code && isLatin(*code) ? kLatin[*code - 0xC0] : "";
    if (piece.empty()) {
      out.push_back('?');
      continue;
    }
    // Capitals: U+00C0..U+00DE (but the multiplication sign), and in Latin Extended-A the even
    // code points, the odd ones in U+0139..U+0148 and U+0179..U+017E (Ĺ..Ň, Ź..Ž), and Ÿ.
    const uint32_t c = *code;
    const bool oddCapitals = (c >= 0x139 && c <= 0x148) || (c >= 0x179 && c <= 0x17E);
    const bool capital = (c >= 0xC0 && c <= 0xDE) || c == 0x178 ||
                         (c >= 0x100 && c != 0x138 && c != 0x17F && (c % 2 == 1) == oddCapitals);
    if (capital) piece[0] = static_cast<char>(piece[0] - 'a' + 'A');
    out += piece;
  }
  return out;
}

}  // namespace globe::places
