// "Go to" in `globe view`: a typed "lat, lon" (decimal degrees, latitude first, as map sites take
// it) or the name of a place from a small gazetteer compiled into the program: peaks, parks and
// towns of the bundled data (Mount Fuji, Zion, eastern England) and a few world cities.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "core/result.hpp"

namespace globe::app {

struct Place {
  const char* name;
  double latitudeDegrees;
  double longitudeDegrees;
};

std::span<const Place> gazetteer();

struct GoToTarget {
  std::string name;  // the place's name, or the coordinates as typed back
  double latitudeDegrees = 0;
  double longitudeDegrees = 0;
};

// "35.36, 138.73", "35.36 138.73", or a place name (case and spaces ignored; a unique prefix such
// as "angels" will do). Errors say what was wrong and name a few places.
Result<GoToTarget> parseGoTo(std::string_view text);

}  // namespace globe::app
