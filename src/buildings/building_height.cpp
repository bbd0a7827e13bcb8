#include "buildings/building_height.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace globe::buildings {

std::optional<double> parseMeters(const std::string& text) {
  size_t begin = 0;
  while (begin < text.size() && std::isspace(static_cast<unsigned char>(text[begin])) != 0) ++begin;
  if (begin == text.size()) return std::nullopt;
  const char* start = text.c_str() + begin;
  char* end = nullptr;
  const double value = std::strtod(start, &end);
  if (end == start || !std::isfinite(value)) return std::nullopt;
  std::string rest(end);
  std::string tail;
  for (const char c : rest) {
    if (std::isspace(static_cast<unsigned char>(c)) == 0) tail += c;
  }
  if (!tail.empty() && tail != "m") return std::nullopt;
  return value;
}

BuildingHeight buildingHeight(const HeightFields& fields, double levelHeightMeters) {
  struct Candidate {
    const std::optional<std::string>* text;
    double scale;
    const char* what;
  };
  const Candidate candidates[] = {{&fields.named, 1.0, "height attribute"},
                                  {&fields.height, 1.0, "height"},
                                  {&fields.levels, levelHeightMeters, "building:levels"}};
  BuildingHeight out;
  for (const Candidate& c : candidates) {
    if (!c.text->has_value()) continue;
    const auto value = parseMeters(**c.text);
    if (!value) {
      if (out.problem.empty()) {
        out.problem = std::string(c.what) + " '" + **c.text + "' is not a number of metres";
      }
      continue;
    }
    const double meters = *value * c.scale;
    if (!(meters > 0) || meters > kMaxBuildingHeightMeters) {
      out.problem = std::string(c.what) + " " + **c.text + " gives " + std::to_string(meters) +
                    " m: not a building's height (above 0, at most " +
                    std::to_string(static_cast<int>(kMaxBuildingHeightMeters)) + " m)";
      return out;
    }
    out.meters = meters;
    out.problem.clear();
    return out;
  }
  return out;
}

}  // namespace globe::buildings
