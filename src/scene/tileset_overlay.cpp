#include "scene/tileset_overlay.hpp"

#include <algorithm>
#include <limits>

namespace globe::scene {

std::optional<double> TilesetOverlay::heightAt(double lon, double lat) const {
  std::optional<double> best;
  for (const auto& tileset : tilesets_) {
    const auto h = tileset->heightAt(lon, lat);
    if (h && (!best || *h > *best)) best = h;
  }
  return best;
}

double TilesetOverlay::maximumHeightMeters() const {
  double highest = -std::numeric_limits<double>::infinity();
  for (const auto& tileset : tilesets_) highest = std::max(highest, tileset->maximumHeightMeters());
  return highest;
}

}  // namespace globe::scene
