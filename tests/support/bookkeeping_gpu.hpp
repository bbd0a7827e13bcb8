// A TileGpu with no GPU: it keeps which meshes and textures would be resident and their bytes, and
// nothing else. For runs that draw nothing (the soak, selection and loading benchmarks) and for
// testing the scene with no GL context.
#pragma once

#include <unordered_map>

#include "scene/tile_gpu.hpp"

namespace globe::testing {

class BookkeepingGpu final : public scene::TileGpu {
 public:
  bool hasTile(const geo::TileId& tile) const override;
  Result<void> prepareTile(const geo::TileId& tile, const terrain::TileMesh& mesh) override;
  bool releaseTile(const geo::TileId& tile) override;

  bool hasImageryTile(uint32_t layer, const geo::TileId& tile) const override;
  Result<void> prepareImageryTile(uint32_t layer, const geo::TileId& tile,
                                  std::span<const uint8_t> rgba, int widthPixels,
                                  int heightPixels) override;
  bool releaseImageryTile(uint32_t layer, const geo::TileId& tile) override;
  uint64_t imageryBytesResident() const override { return imageryBytes_; }

  size_t tilesResident() const { return meshBytes_.size(); }
  size_t imageryTilesResident() const { return textureBytes_.size(); }
  // Vertex bytes of the meshes plus the imagery textures with their mip chains (4/3), as the GL
  // renderer counts them (less its one shared index buffer).
  uint64_t bytesResident() const { return meshBytesTotal_ + imageryBytes_; }
  uint64_t tilesPrepared() const { return tilesPrepared_; }  // ever, replacements included

 private:
  struct TextureKey {
    uint32_t layer;
    geo::TileId tile;
    bool operator==(const TextureKey&) const = default;
  };
  struct TextureKeyHash {
    size_t operator()(const TextureKey& key) const {
      return std::hash<geo::TileId>{}(key.tile) * 31u + key.layer;
    }
  };
  std::unordered_map<geo::TileId, uint64_t> meshBytes_;
  std::unordered_map<TextureKey, uint64_t, TextureKeyHash> textureBytes_;
  uint64_t meshBytesTotal_ = 0, imageryBytes_ = 0, tilesPrepared_ = 0;
};

}  // namespace globe::testing
