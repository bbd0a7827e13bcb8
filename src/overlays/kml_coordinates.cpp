#include "overlays/kml_coordinates.hpp"

#include <array>
#include <cctype>
#include <charconv>
#include <string>

#include "overlays/positions.hpp"

namespace globe::overlays {
namespace {

bool isSpace(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

// Reads one number at text[at]; advances `at` past it.
bool readNumber(std::string_view text, size_t& at, double& value) {
  size_t start = at;
  if (start < text.size() && text[start] == '+') ++start;  // from_chars refuses '+'
  const auto [end, error] = std::from_chars(text.data() + start, text.data() + text.size(), value);
  if (error != std::errc()) return false;
  at = static_cast<size_t>(end - text.data());
  return true;
}

std::string excerpt(std::string_view text, size_t from) {
  size_t end = from;
  while (end < text.size() && !isSpace(text[end]) && end - from < 40) ++end;
  return std::string(text.substr(from, end - from));
}

Result<Position> checked(const std::array<double, 3>& values, size_t count, size_t index) {
  const Position position{values[0], values[1], count == 3 ? values[2] : 0.0};
  if (auto problem = positionProblem(position)) {
    return makeError("coordinate " + std::to_string(index + 1) + ": " + *problem);
  }
  return position;
}

}  // namespace

Result<std::vector<Position>> parseKmlCoordinates(std::string_view text) {
  std::vector<Position> positions;
  size_t at = 0;
  const auto skipSpace = [&] {
    while (at < text.size() && isSpace(text[at])) ++at;
  };
  skipSpace();
  while (at < text.size()) {
    const size_t tupleStart = at;
    std::array<double, 3> values{};
    size_t count = 0;
    for (;;) {
      if (count == values.size() || !readNumber(text, at, values[count])) {
        return makeError("coordinate " + std::to_string(positions.size() + 1) + " \"" +
                         excerpt(text, tupleStart) + "\" is not lon,lat[,alt]");
      }
      ++count;
      skipSpace();
      if (at < text.size() && text[at] == ',') {
        ++at;
        skipSpace();
        continue;
      }
      break;
    }
    if (count < 2) {
      return makeError("coordinate " + std::to_string(positions.size() + 1) + " \"" +
                       excerpt(text, tupleStart) + "\" has no latitude");
    }
    auto position = checked(values, count, positions.size());
    if (!position) return Error{position.error()};
    positions.push_back(*position);
  }
  return positions;
}

Result<Position> parseGxCoord(std::string_view text) {
  std::array<double, 3> values{};
  size_t count = 0;
  size_t at = 0;
  for (;;) {
    while (at < text.size() && isSpace(text[at])) ++at;
    if (at == text.size()) break;
    if (count == values.size() || !readNumber(text, at, values[count])) {
      return makeError("gx:coord \"" + excerpt(text, 0) + "\" is not \"lon lat [alt]\"");
    }
    ++count;
  }
  if (count < 2) return makeError("gx:coord \"" + excerpt(text, 0) + "\" has no latitude");
  return checked(values, count, 0);
}

}  // namespace globe::overlays
