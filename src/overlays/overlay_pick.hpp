// Which placemark's draped line or polygon lies under a point of the ground (a click): what is
// drawn on top wins, as the eye sees it (lines over polygons, later files over earlier).
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <span>

#include "overlays/overlay_model.hpp"

namespace globe::overlays {

struct PlacemarkRef {
  size_t document = 0, placemark = 0;
  bool operator==(const PlacemarkRef&) const = default;
};

// A line is hit within `toleranceMeters` of it; a polygon where it covers the point (even-odd
// over its rings, as it is filled) or within the tolerance of its outline.
std::optional<PlacemarkRef> pickDraped(
    std::span<const std::shared_ptr<const OverlayDocument>> documents, double longitudeDegrees,
    double latitudeDegrees, double toleranceMeters);

}  // namespace globe::overlays
