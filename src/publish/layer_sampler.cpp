#include "publish/layer_sampler.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geo/tiling_scheme.hpp"

namespace globe::publish {
namespace {

constexpr double kRadiansPerDegree = std::numbers::pi / 180;
constexpr size_t kRememberedTiles = size_t{1} << 20;

}  // namespace

LayerSampler::LayerSampler(streaming::ImageryTiles& layer, size_t cachedTiles)
    : layer_(layer),
      tileSizePixels_(layer.manifest().tileSizePixels),
      edgeSamples_(layer.manifest().pixelGrid == formats::ImageryPixelGrid::Edges),
      cachedTiles_(std::max<size_t>(cachedTiles, 8)) {}

Result<Rgba8> LayerSampler::sample(double longitudeDegrees, double latitudeDegrees,
                                   uint32_t level) {
  const auto tile = geo::GeographicTilingScheme::positionToTile(
      longitudeDegrees * kRadiansPerDegree, latitudeDegrees * kRadiansPerDegree, level);
  if (!tile) return Rgba8{0, 0, 0, 0};
  auto present = presentLevel(*tile);
  if (!present) return Error{present.error()};
  if (!*present) return Rgba8{0, 0, 0, 0};
  auto p = bilinear(longitudeDegrees, latitudeDegrees, **present);
  if (!p) return Error{p.error()};
  if (p->alpha <= 0) return Rgba8{0, 0, 0, 0};
  const auto channel = [](double v) {
    return static_cast<uint8_t>(std::clamp(std::lround(v), 0L, 255L));
  };
  return Rgba8{channel(p->red / p->alpha), channel(p->green / p->alpha),
               channel(p->blue / p->alpha), channel(p->alpha * 255)};
}

Result<LayerSampler::Premultiplied> LayerSampler::bilinear(double longitudeDegrees,
                                                           double latitudeDegrees, uint32_t level) {
  // Sample coordinates over the whole level: pixel centres (Area) sit half a pixel in from
  // the tile's edges; edge samples (Edges) lie on them, S − 1 intervals per tile.
  const double columnsPerTile = edgeSamples_ ? tileSizePixels_ - 1.0 : tileSizePixels_;
  const double columns = geo::GeographicTilingScheme::tilesX(level) * columnsPerTile;
  const double rows = geo::GeographicTilingScheme::tilesY(level) * columnsPerTile;
  const double shift = edgeSamples_ ? 0.0 : 0.5;
  const double u = (longitudeDegrees + 180) / 360 * columns - shift;
  const double v = (90 - latitudeDegrees) / 180 * rows - shift;
  const double u0 = std::floor(u), v0 = std::floor(v);
  const double fu = u - u0, fv = v - v0;
  Premultiplied sum;
  for (int dy = 0; dy < 2; ++dy) {
    for (int dx = 0; dx < 2; ++dx) {
      const double weight = (dx == 0 ? 1 - fu : fu) * (dy == 0 ? 1 - fv : fv);
      if (weight <= 0) continue;
      auto t = tap(level, static_cast<int64_t>(u0) + dx, static_cast<int64_t>(v0) + dy);
      if (!t) return Error{t.error()};
      sum.red += weight * t->red;
      sum.green += weight * t->green;
      sum.blue += weight * t->blue;
      sum.alpha += weight * t->alpha;
    }
  }
  return sum;
}

Result<LayerSampler::Premultiplied> LayerSampler::tap(uint32_t level, int64_t column, int64_t row) {
  const int64_t s = edgeSamples_ ? tileSizePixels_ - 1 : tileSizePixels_;
  const int64_t tilesX = geo::GeographicTilingScheme::tilesX(level);
  const int64_t tilesY = geo::GeographicTilingScheme::tilesY(level);
  // Columns wrap around the antimeridian; rows stop at the poles (the last edge sample row is
  // the south pole's).
  const int64_t columns = tilesX * s;
  column = ((column % columns) + columns) % columns;
  row = std::clamp<int64_t>(row, 0, edgeSamples_ ? tilesY * s : tilesY * s - 1);
  const int64_t tileY = std::min(row / s, tilesY - 1);
  const geo::TileId tile{level, static_cast<uint32_t>(column / s), static_cast<uint32_t>(tileY)};
  auto found = image(tile);
  if (!found) return Error{found.error()};
  if (*found != nullptr) {
    const formats::ImageRgba& img = **found;
    const size_t x = static_cast<size_t>(column - tile.x * s);
    const size_t y = static_cast<size_t>(row - tileY * s);
    const uint8_t* p = &img.pixels[(y * static_cast<size_t>(img.widthPixels) + x) * 4];
    const double alpha = p[3] / 255.0;
    return Premultiplied{p[0] * alpha, p[1] * alpha, p[2] * alpha, alpha};
  }
  // Beyond where this level's tiles stop: the ancestor the viewer would draw there.
  if (level == 0 || layer_.emptyWhereAbsent()) return Premultiplied{};
  auto present = presentLevel(tile.parent());
  if (!present) return Error{present.error()};
  if (!*present) return Premultiplied{};
  const double shift = edgeSamples_ ? 0.0 : 0.5;
  const double longitude =
      (static_cast<double>(column) + shift) / static_cast<double>(columns) * 360 - 180;
  const double latitude =
      90 - (static_cast<double>(row) + shift) / static_cast<double>(tilesY * s) * 180;
  return bilinear(longitude, latitude, **present);
}

Result<const formats::ImageRgba*> LayerSampler::image(const geo::TileId& tile) {
  if (lastTile_ == tile) return lastImage_;
  auto it = images_.find(tile);
  if (it == images_.end()) {
    auto has = layer_.hasTile(tile);
    if (!has) return Error{has.error()};
    std::optional<formats::ImageRgba> decoded;
    if (*has) {
      auto loaded = layer_.loadImage(tile);
      if (!loaded) return Error{loaded.error()};
      decoded = std::move(*loaded);
      if (decoded && (decoded->widthPixels != static_cast<int>(tileSizePixels_) ||
                      decoded->heightPixels != static_cast<int>(tileSizePixels_))) {
        return makeError(layer_.tileLocation(tile) + ": " + geo::tileName(tile) + " is " +
                         std::to_string(decoded->widthPixels) + "×" +
                         std::to_string(decoded->heightPixels) + " pixels, not the layer's " +
                         std::to_string(tileSizePixels_));
      }
    }
    if (images_.size() >= cachedTiles_) {
      images_.erase(imageOrder_.front());
      imageOrder_.pop_front();
    }
    it = images_.emplace(tile, std::move(decoded)).first;
    imageOrder_.push_back(tile);
  }
  lastTile_ = tile;
  lastImage_ = it->second ? &*it->second : nullptr;
  return lastImage_;
}

Result<std::optional<uint32_t>> LayerSampler::presentLevel(const geo::TileId& tile) {
  if (auto it = presentLevels_.find(tile); it != presentLevels_.end()) return it->second;
  std::optional<uint32_t> level;
  auto has = layer_.hasTile(tile);
  if (!has) return Error{has.error()};
  if (*has) {
    level = tile.level;
  } else if (tile.level > 0 && !layer_.emptyWhereAbsent()) {
    auto above = presentLevel(tile.parent());
    if (!above) return Error{above.error()};
    level = *above;
  }
  // Forgotten now and then: a sweep over a large region would otherwise keep every tile.
  if (presentLevels_.size() >= kRememberedTiles) presentLevels_.clear();
  presentLevels_.emplace(tile, level);
  return level;
}

}  // namespace globe::publish
