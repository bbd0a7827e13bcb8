#include "overlays/overlay_imagery.hpp"

#include <algorithm>

#include "geo/tiling_scheme.hpp"
#include "overlays/drape_raster.hpp"

namespace globe::overlays {
namespace {

constexpr uint32_t kTileSizePixels = 256;

// The part of the set's box on the globe (a box running past ±180° covers every longitude).
formats::BoundsDegrees globeBounds(const DegreesBox& box) {
  if (box.west < -180.0 || box.east > 180.0) {
    return {-180.0, std::max(box.south, -90.0), 180.0, std::min(box.north, 90.0)};
  }
  return {box.west, std::max(box.south, -90.0), box.east, std::min(box.north, 90.0)};
}

}  // namespace

std::unique_ptr<OverlayImagery> OverlayImagery::create(
    std::span<const std::shared_ptr<const OverlayDocument>> documents, std::string name) {
  DrapeSet set = makeDrapeSet(documents);
  return std::unique_ptr<OverlayImagery>(new OverlayImagery(std::move(set), std::move(name)));
}

OverlayImagery::OverlayImagery(DrapeSet set, std::string name)
    : set_(std::move(set)), name_(std::move(name)) {
  manifest_.tileSizePixels = kTileSizePixels;
  manifest_.pixelGrid = formats::ImageryPixelGrid::Edges;
  manifest_.kind = formats::LayerKind::Imagery;
  manifest_.bounds = globeBounds(set_.bounds);
  for (uint32_t level = 0; level <= kOverlayMaxLevel; ++level) {
    formats::ImageryLevelInfo info;
    info.level = level;
    info.bounds = manifest_.bounds;
    manifest_.levels.push_back(info);
  }
  formats::ImagerySourceInfo source;
  source.path = name_;
  source.driver = "overlay";
  source.crs = "EPSG:4326";
  source.pixelDegrees =
      180.0 / ((kTileSizePixels - 1) * static_cast<double>(1u << kOverlayMaxLevel));
  source.bounds = manifest_.bounds;
  source.finestLevel = kOverlayMaxLevel;
  source.bands = "RGBA";
  manifest_.sources.push_back(source);
}

Result<bool> OverlayImagery::hasTile(const geo::TileId& tile) {
  return peekTile(tile) == Peek::Present;
}

streaming::ImageryTiles::Peek OverlayImagery::peekTile(const geo::TileId& tile) {
  if (!geo::GeographicTilingScheme::isValid(tile) || tile.level > kOverlayMaxLevel) {
    return Peek::Absent;
  }
  return touchesTile(set_, tile, kTileSizePixels) ? Peek::Present : Peek::Absent;
}

Result<std::optional<formats::ImageRgba>> OverlayImagery::loadImage(const geo::TileId& tile) {
  if (peekTile(tile) != Peek::Present) return std::optional<formats::ImageRgba>{};
  return std::optional<formats::ImageRgba>{drawTile(set_, tile, kTileSizePixels)};
}

std::string OverlayImagery::tileLocation(const geo::TileId& tile) const {
  return name_ + " tile " + std::to_string(tile.level) + "/" + std::to_string(tile.x) + "/" +
         std::to_string(tile.y);
}

}  // namespace globe::overlays
