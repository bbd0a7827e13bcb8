// heightmap-1.0 written as CesiumJS's HeightmapTerrainData reads it, for the exporter.
#include <algorithm>
#include <cmath>
#include <vector>

#include "formats/quantized_mesh.hpp"

namespace globe::formats {

std::vector<std::byte> encodeHeightmapTile(const HeightmapTile& tile) {
  std::vector<std::byte> bytes;
  bytes.reserve(tile.heightMeters.size() * 2 + 1 + tile.waterMask.size());
  for (const double heightMeters : tile.heightMeters) {
    const double h = std::isfinite(heightMeters) ? heightMeters : 0.0;  // no height: sea level
    const auto raw =
        static_cast<uint16_t>(std::clamp(std::round((h + 1000.0) * 5.0), 0.0, 65535.0));
    bytes.push_back(static_cast<std::byte>(raw & 0xFFU));  // little-endian
    bytes.push_back(static_cast<std::byte>(raw >> 8));
  }
  bytes.push_back(static_cast<std::byte>(tile.childMask));
  for (const uint8_t water : tile.waterMask) bytes.push_back(static_cast<std::byte>(water));
  return bytes;
}

}  // namespace globe::formats
