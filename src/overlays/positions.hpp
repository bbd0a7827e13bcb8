// Checks every reader applies to positions, and ring closing.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "overlays/overlay_model.hpp"

namespace globe::overlays {

// What is wrong with a position ("latitude 95 is outside -90..90"), or nullopt: longitude and
// latitude must be finite and within ±180 and ±90 degrees (±180 itself allowed), the height
// finite.
std::optional<std::string> positionProblem(const Position& position);

// Appends the first position when the ring does not end on it.
void closeRing(std::vector<Position>& ring);

// A ring worth drawing: at least three distinct corners once closed (four positions).
bool isUsableRing(const std::vector<Position>& closedRing);

}  // namespace globe::overlays
