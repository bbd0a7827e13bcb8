#include "places/coordinates.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

namespace globe::places {
namespace {

struct Token {
  enum Kind { Number, Letter, Unit, LetterUnit, Separator } kind;
  double value = 0;
  char letter = 0;
  bool negative = false;
};

// Numbers, hemisphere letters, unit marks (° ' " ′ ″, and d m as letters), separators (, ; /);
// nullopt for anything else (a name).
std::optional<std::vector<Token>> tokenize(std::string_view text) {
  std::vector<Token> tokens;
  size_t i = 0;
  while (i < text.size()) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (std::isspace(c) != 0) {
      ++i;
    } else if (c == ',' || c == ';' || c == '/') {
      tokens.push_back({Token::Separator});
      ++i;
    } else if (std::isdigit(c) != 0 || c == '.' || c == '-' || c == '+') {
      const std::string number(text.substr(i, 32));
      char* end = nullptr;
      const double value = std::strtod(number.c_str(), &end);
      if (end == number.c_str()) return std::nullopt;
      tokens.push_back({Token::Number, std::fabs(value), 0, number[0] == '-'});
      i += static_cast<size_t>(end - number.c_str());
    } else if (c == '\'' || c == '"') {
      tokens.push_back({Token::Unit});
      ++i;
    } else if (text.substr(i, 2) == "\xC2\xB0" || text.substr(i, 2) == "\xC2\xBA") {  // ° º
      tokens.push_back({Token::Unit});
      i += 2;
    } else if (text.substr(i, 3) == "\xE2\x80\xB2" || text.substr(i, 3) == "\xE2\x80\xB3" ||
               text.substr(i, 3) == "\xE2\x80\x99" || text.substr(i, 3) == "\xE2\x80\x9D") {
      tokens.push_back({Token::Unit});  // ′ ″ ’ ”
      i += 3;
    } else if (std::isalpha(c) != 0) {
      const bool alone =
          i + 1 >= text.size() || std::isalpha(static_cast<unsigned char>(text[i + 1])) == 0;
      const auto upper = static_cast<char>(std::toupper(c));
      if (!alone) return std::nullopt;  // a word: a name
      if (upper == 'N' || upper == 'S' || upper == 'E' || upper == 'W') {
        tokens.push_back({Token::Letter, 0, upper});
      } else if (upper == 'D' || upper == 'M') {
        tokens.push_back({Token::LetterUnit, 0, upper});
      } else {
        return std::nullopt;
      }
      ++i;
    } else {
      return std::nullopt;
    }
  }
  return tokens;
}

// One coordinate: degrees, minutes, seconds (up to three numbers) and its hemisphere letter.
struct Part {
  std::vector<double> numbers;
  char hemisphere = 0;
  bool negative = false;
  bool letterUnits = false;  // "35d21m38s": its s is seconds, not south
};

// The tokens cut into coordinates: at separators; at hemisphere letters (ending a part when they
// follow numbers, "35.36N 138.73E"; starting one when they lead, "N35.36 E138.73"); else two
// plain numbers, or two halves of four or six.
std::vector<Part> partsOf(const std::vector<Token>& tokens) {
  const bool leading = !tokens.empty() && tokens.front().kind == Token::Letter;
  std::vector<Part> parts(1);
  for (const Token& t : tokens) {
    Part* part = &parts.back();
    switch (t.kind) {
      case Token::Number:
        if (!leading && part->hemisphere != 0) part = &parts.emplace_back();
        if (part->numbers.empty()) part->negative = t.negative;
        part->numbers.push_back(t.value);
        break;
      case Token::LetterUnit:
        part->letterUnits = true;
        break;
      case Token::Letter:
        if (t.letter == 'S' && part->letterUnits && part->hemisphere == 0 &&
            part->numbers.size() == 3) {
          break;  // seconds
        }
        if (leading && !part->numbers.empty()) part = &parts.emplace_back();
        if (part->hemisphere != 0) part = &parts.emplace_back();
        part->hemisphere = t.letter;
        break;
      case Token::Unit:
        break;
      case Token::Separator:
        if (!part->numbers.empty() || part->hemisphere != 0) parts.emplace_back();
        break;
    }
  }
  if (parts.back().numbers.empty() && parts.back().hemisphere == 0) parts.pop_back();
  if (parts.size() == 1 && parts[0].hemisphere == 0) {
    const std::vector<double> all = parts[0].numbers;
    const size_t half = all.size() / 2;
    if (all.size() != 2 && all.size() != 4 && all.size() != 6) return {};
    std::vector<bool> negative;
    for (const Token& t : tokens) {
      if (t.kind == Token::Number) negative.push_back(t.negative);
    }
    parts = {Part{{all.begin(), all.begin() + static_cast<ptrdiff_t>(half)}, 0, negative[0]},
             Part{{all.begin() + static_cast<ptrdiff_t>(half), all.end()}, 0, negative[half]}};
  }
  return parts;
}

double decimalOf(const Part& part) {
  double value = 0;
  double scale = 1;
  for (double n : part.numbers) {
    value += n / scale;
    scale *= 60;
  }
  const bool southOrWest = part.hemisphere == 'S' || part.hemisphere == 'W';
  return part.negative != southOrWest ? -value : value;
}

}  // namespace

std::optional<Result<LatLon>> parseCoordinates(std::string_view text) {
  auto tokens = tokenize(text);
  if (!tokens || tokens->empty()) return std::nullopt;
  const std::vector<Part> parts = partsOf(*tokens);
  if (parts.size() != 2) return std::nullopt;
  for (const Part& p : parts) {
    if (p.numbers.empty() || p.numbers.size() > 3) return std::nullopt;
    for (size_t k = 1; k < p.numbers.size(); ++k) {
      if (p.numbers[k] >= 60) {
        return Result<LatLon>(
            makeError("\"" + std::string(text) + "\": minutes and seconds must be below 60"));
      }
    }
  }
  const auto latitudeLetter = [](char h) { return h == 'N' || h == 'S'; };
  const auto longitudeLetter = [](char h) { return h == 'E' || h == 'W'; };
  if ((latitudeLetter(parts[0].hemisphere) && latitudeLetter(parts[1].hemisphere)) ||
      (longitudeLetter(parts[0].hemisphere) && longitudeLetter(parts[1].hemisphere))) {
    return Result<LatLon>(
        makeError("\"" + std::string(text) + "\": one latitude (N/S) and one longitude (E/W)"));
  }
  double latitude = decimalOf(parts[0]);
  double longitude = decimalOf(parts[1]);
  // Longitude first where its letters say so, or where the first number cannot be a latitude.
  if (longitudeLetter(parts[0].hemisphere) || latitudeLetter(parts[1].hemisphere) ||
      (parts[0].hemisphere == 0 && parts[1].hemisphere == 0 && std::fabs(latitude) > 90 &&
       std::fabs(longitude) <= 90)) {
    std::swap(latitude, longitude);
  }
  if (!std::isfinite(latitude) || !std::isfinite(longitude) || std::fabs(latitude) > 90 ||
      std::fabs(longitude) > 180) {
    return Result<LatLon>(makeError("\"" + std::string(text) +
                                    "\": latitude must be in -90..90 and longitude in -180..180"));
  }
  return Result<LatLon>(LatLon{latitude, longitude});
}

}  // namespace globe::places
