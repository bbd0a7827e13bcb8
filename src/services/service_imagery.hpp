// What every imagery service layer shares (XYZ, TMS, WMTS, PMTiles): the quadtree tiles it can
// fill, and each tile made by mapping its 256×256 edge samples (formats::ImageryPixelGrid::Edges)
// through the service's tiling (tile_matrix.hpp) into its tiles' pixels, bilinearly between
// their centres: Web Mercator drapes on the geographic tiles without distortion, and tiles meet
// without seams. Where the service has no tile, its pixels are transparent; a quadtree tile with
// nothing at all is absent, so its parent is drawn.
#pragma once

#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "services/recent_items.hpp"
#include "services/tile_matrix.hpp"
#include "streaming/imagery_tiles.hpp"

namespace globe::services {

struct ImageryServiceDescription {
  std::string location;  // as the user gave it
  std::string driver;    // "XYZ", "TMS", "WMTS", "PMTiles"
  TileMatrixSet tiling;
  formats::BoundsDegrees bounds{-180, -90, 180, 90};  // where the service has imagery
  std::string attribution;
  bool remote = false;
};

class ServiceImagery : public streaming::ImageryTiles {
 public:
  static constexpr uint32_t kTileSizePixels = 256;

  explicit ServiceImagery(ImageryServiceDescription description);

  const formats::LayerManifest& manifest() const override { return manifest_; }
  const std::string& location() const override { return description_.location; }
  bool remote() const override { return description_.remote; }
  std::string attribution() const override { return description_.attribution; }
  Result<bool> hasTile(const geo::TileId& tile) override;
  Peek peekTile(const geo::TileId& tile) override;
  Result<std::optional<formats::ImageRgba>> loadImage(const geo::TileId& tile) override;
  std::string tileLocation(const geo::TileId& tile) const override;

  uint64_t sourceTilesFetched() const { return fetched_; }

 protected:
  // The encoded tile (PNG, JPEG, WebP) at a matrix's column and row; nullopt when the service
  // has none there (404).
  virtual Result<std::optional<std::vector<std::byte>>> fetchSourceTile(size_t matrix,
                                                                        uint64_t column,
                                                                        uint64_t row) = 0;
  virtual std::string sourceTileUrl(size_t matrix, uint64_t column, uint64_t row) const = 0;
  const TileMatrixSet& tiling() const { return description_.tiling; }

 private:
  struct Decoded {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba;
  };
  using Key = std::tuple<size_t, uint64_t, uint64_t>;
  Result<std::shared_ptr<const Decoded>> sourceTile(
      const Key& key, std::map<Key, std::shared_ptr<const Decoded>>& local);
  size_t matrixForTile(const geo::TileId& tile) const;

  ImageryServiceDescription description_;
  formats::LayerManifest manifest_;
  std::atomic<uint64_t> fetched_{0};
  // Decoded source tiles (null: the service has none there).
  RecentItems<Key, std::shared_ptr<const Decoded>> recent_{96};
};

}  // namespace globe::services
