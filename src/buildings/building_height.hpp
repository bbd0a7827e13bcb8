// A building's height from its attributes: the one the user named, else OSM's `height`, else
// `building:levels` × a storey's height. OSM's `height` is the roof's height above the ground
// (a number of metres, "12", "12.5 m"); anything else is not read as a height.
#pragma once

#include <optional>
#include <string>

namespace globe::buildings {

// Heights past this are refused as absurd (the tallest building stands 828 m).
inline constexpr double kMaxBuildingHeightMeters = 1000;

// The attributes' text as read (nullopt: the feature has no such field, or it is null/empty).
struct HeightFields {
  std::optional<std::string> named;   // --height-attribute's field
  std::optional<std::string> height;  // `height`
  std::optional<std::string> levels;  // `building:levels`
};

struct BuildingHeight {
  std::optional<double> meters;  // nullopt: no usable height
  std::string problem;           // why a value present was refused ("" where none was present)
};

// "12", "12.5", "12 m", "12.5m" (surrounding spaces allowed) as metres; nullopt otherwise.
std::optional<double> parseMeters(const std::string& text);

// The first of named, height, levels × levelHeightMeters that reads as a number; refused (with a
// problem) when it is not positive or is above kMaxBuildingHeightMeters, or when every field
// present fails to read as a number.
BuildingHeight buildingHeight(const HeightFields& fields, double levelHeightMeters);

}  // namespace globe::buildings
