// The ruler drawn on the ground as one more overlay document, shown after the user's files: its
// path as a clamped line (a closed ring lightly filled) and a small icon at each point, no text.
#pragma once

#include <memory>
#include <vector>

#include "apps/globe/ruler.hpp"
#include "overlays/overlay_model.hpp"

namespace globe::app {

inline constexpr overlays::Rgba kRulerColor{255, 200, 0, 255};
inline constexpr double kRulerLineWidthPixels = 3;

// Null for a ruler without points.
std::shared_ptr<const overlays::OverlayDocument> rulerDocument(const Ruler& ruler);

// The user's documents, then the ruler's when there is one: what the scene shows.
std::vector<std::shared_ptr<const overlays::OverlayDocument>> withRuler(
    std::vector<std::shared_ptr<const overlays::OverlayDocument>> documents,
    const std::shared_ptr<const overlays::OverlayDocument>& ruler);

}  // namespace globe::app
