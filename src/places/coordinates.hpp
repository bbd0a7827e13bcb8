// A position typed as people type it: "35.36, 138.73" (latitude first, as map sites take it),
// "138.73 35.36" (longitude first when the first number cannot be a latitude), with hemisphere
// letters ("35.36N 138.73E", "N35.36 E138.73", "35.36 N, 138.73 E", either order then), and in
// degrees, minutes and seconds ("35°21'38\"N 138°43'39\"E", "35 21 38 N 138 43 39 E",
// "35d21m38s").
#pragma once

#include <optional>
#include <string_view>

#include "core/result.hpp"

namespace globe::places {

struct LatLon {
  double latitudeDegrees = 0;
  double longitudeDegrees = 0;
};

// nullopt when the text is not a position at all (a name, then); an error when it is one but
// out of range or ambiguous in a way that cannot be settled, saying why.
std::optional<Result<LatLon>> parseCoordinates(std::string_view text);

}  // namespace globe::places
