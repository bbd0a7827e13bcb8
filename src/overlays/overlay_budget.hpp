// What one overlay file may put on the globe, counted as its readers go: placemarks and
// vertices, not bytes (a 1.7 MB KMZ can hold 480 MiB of placemarks). Past a limit the reader
// stops with an error naming the file and the limit, before memory and time run away.
#pragma once

#include <cstddef>
#include <string>

#include "core/result.hpp"
#include "overlays/overlay_model.hpp"

namespace globe::overlays {

inline constexpr size_t kMaxOverlayPlacemarks = 500'000;
inline constexpr size_t kMaxOverlayVertices = 10'000'000;

class OverlayBudget {
 public:
  explicit OverlayBudget(std::string where) : where_(std::move(where)) {}
  // Counts the placemark's vertices and appends it to `document`; an error instead once the file
  // is past either limit.
  Result<void> append(Placemark placemark, OverlayDocument& document);

 private:
  std::string where_;  // the file, for messages
  size_t placemarks_ = 0;
  size_t vertices_ = 0;
};

}  // namespace globe::overlays
