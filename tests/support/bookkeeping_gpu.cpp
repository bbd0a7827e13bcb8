#include "tests/support/bookkeeping_gpu.hpp"

#include <string>

namespace globe::testing {

bool BookkeepingGpu::hasTile(const geo::TileId& tile) const { return meshBytes_.contains(tile); }

Result<void> BookkeepingGpu::prepareTile(const geo::TileId& tile, const terrain::TileMesh& mesh) {
  if (mesh.vertices.empty()) return makeError("tile mesh with no vertices");
  releaseTile(tile);
  const uint64_t bytes = mesh.vertices.size() * sizeof(float);
  meshBytes_[tile] = bytes;
  meshBytesTotal_ += bytes;
  ++tilesPrepared_;
  return {};
}

bool BookkeepingGpu::releaseTile(const geo::TileId& tile) {
  const auto found = meshBytes_.find(tile);
  if (found == meshBytes_.end()) return false;
  meshBytesTotal_ -= found->second;
  meshBytes_.erase(found);
  return true;
}

bool BookkeepingGpu::hasImageryTile(uint32_t layer, const geo::TileId& tile) const {
  return textureBytes_.contains({layer, tile});
}

Result<void> BookkeepingGpu::prepareImageryTile(uint32_t layer, const geo::TileId& tile,
                                                std::span<const uint8_t> rgba, int widthPixels,
                                                int heightPixels) {
  if (widthPixels <= 0 || heightPixels <= 0 ||
      rgba.size() != static_cast<size_t>(widthPixels) * static_cast<size_t>(heightPixels) * 4) {
    return makeError("imagery tile of " + std::to_string(rgba.size()) + " bytes is not " +
                     std::to_string(widthPixels) + "x" + std::to_string(heightPixels) + " RGBA");
  }
  releaseImageryTile(layer, tile);
  const uint64_t bytes = rgba.size() * 4 / 3;  // the mip chain adds a third
  textureBytes_[{layer, tile}] = bytes;
  imageryBytes_ += bytes;
  return {};
}

bool BookkeepingGpu::releaseImageryTile(uint32_t layer, const geo::TileId& tile) {
  const auto found = textureBytes_.find({layer, tile});
  if (found == textureBytes_.end()) return false;
  imageryBytes_ -= found->second;
  textureBytes_.erase(found);
  return true;
}

}  // namespace globe::testing
