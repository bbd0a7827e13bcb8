#include "tiling/pack_summary.hpp"

#include <algorithm>

#include "geo/tiling_scheme.hpp"

namespace globe::tiling {

PackSummary summarise(const formats::Pack& pack) {
  PackSummary summary;
  for (size_t slot = 0; slot < pack.entries.size(); ++slot) {
    const formats::PackEntry& entry = pack.entries[slot];
    if (!entry.present()) continue;
    ++summary.tiles;
    const auto rect = geo::GeographicTilingScheme::tileRectangle(
        formats::tileOfSlot(pack.id, slot, pack.layout.tilesPerSide));
    const double toDegrees = 180.0 / 3.14159265358979323846;
    summary.bounds.west = std::min(summary.bounds.west, rect.westRadians * toDegrees);
    summary.bounds.south = std::min(summary.bounds.south, rect.southRadians * toDegrees);
    summary.bounds.east = std::max(summary.bounds.east, rect.eastRadians * toDegrees);
    summary.bounds.north = std::max(summary.bounds.north, rect.northRadians * toDegrees);
    summary.range.include(entry.vertexRange);
  }
  return summary;
}

}  // namespace globe::tiling
