// A manifest's bounds in degrees as JSON ({"west", "south", "east", "north"}), both ways.
#pragma once

#include <nlohmann/json.hpp>

#include "formats/pyramid_manifest.hpp"

namespace globe::formats {

inline nlohmann::json boundsToJson(const BoundsDegrees& b) {
  return {{"west", b.west}, {"south", b.south}, {"east", b.east}, {"north", b.north}};
}

inline BoundsDegrees boundsFromJson(const nlohmann::json& j) {
  return {j.at("west").get<double>(), j.at("south").get<double>(), j.at("east").get<double>(),
          j.at("north").get<double>()};
}

}  // namespace globe::formats
