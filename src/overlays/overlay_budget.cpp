#include "overlays/overlay_budget.hpp"

#include <utility>

namespace globe::overlays {

Result<void> OverlayBudget::append(Placemark placemark, OverlayDocument& document) {
  for (const Geometry& geometry : placemark.geometries) {
    for (const auto& ring : geometry.rings) vertices_ += ring.size();
  }
  if (++placemarks_ > kMaxOverlayPlacemarks) {
    return makeError(where_ + ": more than " + std::to_string(kMaxOverlayPlacemarks) +
                     " placemarks (features), the most one overlay file may hold; split it");
  }
  if (vertices_ > kMaxOverlayVertices) {
    return makeError(where_ + ": more than " + std::to_string(kMaxOverlayVertices) +
                     " vertices, the most one overlay file may hold; simplify or split it");
  }
  document.placemarks.push_back(std::move(placemark));
  return {};
}

}  // namespace globe::overlays
