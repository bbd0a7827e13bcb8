#include "overlays/positions.hpp"

#include <cmath>
#include <sstream>

namespace globe::overlays {
namespace {

std::string number(double value) {
  std::ostringstream out;
  out.precision(10);
  out << value;
  return out.str();
}

bool samePlace(const Position& a, const Position& b) {
  return a.longitudeDegrees == b.longitudeDegrees && a.latitudeDegrees == b.latitudeDegrees &&
         a.heightMeters == b.heightMeters;
}

}  // namespace

std::optional<std::string> positionProblem(const Position& position) {
  // The negated comparisons also catch NaN.
  if (!(std::fabs(position.longitudeDegrees) <= 180)) {
    return "longitude " + number(position.longitudeDegrees) + " is outside -180..180";
  }
  if (!(std::fabs(position.latitudeDegrees) <= 90)) {
    return "latitude " + number(position.latitudeDegrees) + " is outside -90..90";
  }
  if (!std::isfinite(position.heightMeters)) {
    return "height " + number(position.heightMeters) + " is not a finite number";
  }
  return std::nullopt;
}

void closeRing(std::vector<Position>& ring) {
  if (!ring.empty() && !samePlace(ring.front(), ring.back())) ring.push_back(ring.front());
}

bool isUsableRing(const std::vector<Position>& closedRing) { return closedRing.size() >= 4; }

}  // namespace globe::overlays
