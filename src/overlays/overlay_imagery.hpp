// The overlays' draped part as an imagery layer (streaming::ImageryTiles): its tiles are drawn
// on demand on the loader's threads (overlays/drape_raster.hpp), so the scene streams, caches and
// drapes them like any other layer, and they follow the terrain at every level of detail.
#pragma once

#include <memory>
#include <span>
#include <string>

#include "overlays/drape_set.hpp"
#include "streaming/imagery_tiles.hpp"

namespace globe::overlays {

// Overlay tiles go this deep: texels of about 0.3 m, so lines stay sharp down to street scale.
inline constexpr uint32_t kOverlayMaxLevel = 18;

class OverlayImagery final : public streaming::ImageryTiles {
 public:
  // `name` is what messages call the layer (the files' names).
  static std::unique_ptr<OverlayImagery> create(
      std::span<const std::shared_ptr<const OverlayDocument>> documents, std::string name);
  // Nothing draped: no tile anywhere.
  bool empty() const { return set_.empty(); }

  const formats::LayerManifest& manifest() const override { return manifest_; }
  const std::string& location() const override { return name_; }
  bool remote() const override { return false; }
  bool emptyWhereAbsent() const override { return true; }
  Result<bool> hasTile(const geo::TileId& tile) override;
  Peek peekTile(const geo::TileId& tile) override;
  Result<std::optional<formats::ImageRgba>> loadImage(const geo::TileId& tile) override;
  std::string tileLocation(const geo::TileId& tile) const override;

 private:
  OverlayImagery(DrapeSet set, std::string name);
  DrapeSet set_;
  std::string name_;
  formats::LayerManifest manifest_;
};

}  // namespace globe::overlays
