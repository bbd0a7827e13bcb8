#include "services/service_imagery.hpp"

#include <algorithm>
#include <cmath>

#include "formats/image_io.hpp"
#include "geo/cartographic.hpp"
#include "geo/tiling_scheme.hpp"

namespace globe::services {
namespace {

constexpr double kDegreesPerMeterAtEquator = 360.0 / (2 * 3.141592653589793 * 6378137.0);

double unitsToDegrees(TileCrs crs, double units) {
  return crs == TileCrs::Geographic ? units : units * kDegreesPerMeterAtEquator;
}

bool overlaps(const formats::BoundsDegrees& a, const formats::BoundsDegrees& b) {
  return a.west < b.east && b.west < a.east && a.south < b.north && b.south < a.north;
}

}  // namespace

ServiceImagery::ServiceImagery(ImageryServiceDescription description)
    : description_(std::move(description)) {
  const TileMatrixSet& set = description_.tiling;
  const double finestDegrees =
      set.matrices.empty() ? 1.0 : unitsToDegrees(set.crs, set.matrices.back().unitsPerPixel);
  // The level whose edge samples are as fine as the service's finest pixels.
  const double level = std::log2(180.0 / ((kTileSizePixels - 1) * finestDegrees));
  const auto maxLevel = static_cast<uint32_t>(
      std::clamp(std::ceil(level - 0.25), 0.0, static_cast<double>(geo::kMaxLevel)));
  manifest_.tileSizePixels = kTileSizePixels;
  manifest_.pixelGrid = formats::ImageryPixelGrid::Edges;
  manifest_.kind = formats::LayerKind::Imagery;
  manifest_.bounds = description_.bounds;
  for (uint32_t l = 0; l <= maxLevel; ++l) {
    formats::ImageryLevelInfo info;
    info.level = l;
    info.bounds = description_.bounds;
    manifest_.levels.push_back(info);
  }
  formats::ImagerySourceInfo source;
  source.path = description_.location;
  source.driver = description_.driver;
  source.crs = set.crs == TileCrs::WebMercator ? "EPSG:3857" : "EPSG:4326";
  source.pixelDegrees = finestDegrees;
  source.bounds = description_.bounds;
  source.finestLevel = maxLevel;
  source.bands = "RGBA";
  manifest_.sources.push_back(source);
}

Result<bool> ServiceImagery::hasTile(const geo::TileId& tile) {
  return peekTile(tile) == Peek::Present;
}

streaming::ImageryTiles::Peek ServiceImagery::peekTile(const geo::TileId& tile) {
  if (!geo::GeographicTilingScheme::isValid(tile) || tile.level > manifest_.maxLevel()) {
    return Peek::Absent;
  }
  const auto r = geo::GeographicTilingScheme::tileRectangle(tile);
  const formats::BoundsDegrees b{
      geo::radiansToDegrees(r.westRadians), geo::radiansToDegrees(r.southRadians),
      geo::radiansToDegrees(r.eastRadians), geo::radiansToDegrees(r.northRadians)};
  return overlaps(b, description_.bounds) ? Peek::Present : Peek::Absent;
}

size_t ServiceImagery::matrixForTile(const geo::TileId& tile) const {
  const auto r = geo::GeographicTilingScheme::tileRectangle(tile);
  const double sampleDegrees = geo::radiansToDegrees(r.widthRadians()) / (kTileSizePixels - 1);
  // Web Mercator's pixels shrink towards the poles: matched where the tile is nearest the equator.
  const double north = geo::radiansToDegrees(r.northRadians);
  const double south = geo::radiansToDegrees(r.southRadians);
  const double lat = south > 0 ? south : north < 0 ? north : 0.0;
  return matrixFor(tiling(), sampleDegrees * crsUnitsPerDegree(tiling().crs, lat));
}

std::string ServiceImagery::tileLocation(const geo::TileId& tile) const {
  const auto r = geo::GeographicTilingScheme::tileRectangle(tile);
  const size_t m = matrixForTile(tile);
  const TileMatrix& matrix = tiling().matrices.at(m);
  const auto xy =
      toCrs(tiling().crs, geo::radiansToDegrees((r.westRadians + r.eastRadians) / 2),
            std::clamp(geo::radiansToDegrees((r.southRadians + r.northRadians) / 2), -85.0, 85.0));
  if (!xy) return location();
  const auto column = static_cast<uint64_t>(
      std::clamp((xy->first - matrix.originX) / (matrix.unitsPerPixel * matrix.tileWidth), 0.0,
                 static_cast<double>(matrix.columns - 1)));
  const auto row = static_cast<uint64_t>(
      std::clamp((matrix.originY - xy->second) / (matrix.unitsPerPixel * matrix.tileHeight), 0.0,
                 static_cast<double>(matrix.rows - 1)));
  return sourceTileUrl(m, column, row);
}

Result<std::shared_ptr<const ServiceImagery::Decoded>> ServiceImagery::sourceTile(
    const Key& key, std::map<Key, std::shared_ptr<const Decoded>>& local) {
  if (auto it = local.find(key); it != local.end()) return it->second;
  if (auto kept = recent_.find(key)) {
    local.emplace(key, *kept);
    return *kept;
  }
  const auto& [m, column, row] = key;
  auto bytes = fetchSourceTile(m, column, row);
  if (!bytes) return Error{bytes.error()};
  std::shared_ptr<const Decoded> decoded;
  if (*bytes) {
    ++fetched_;
    auto image = formats::decodeImageRgba(**bytes, sourceTileUrl(m, column, row));
    if (!image) return Error{image.error()};
    auto d = std::make_shared<Decoded>();
    d->width = static_cast<uint32_t>(image->widthPixels);
    d->height = static_cast<uint32_t>(image->heightPixels);
    d->rgba = std::move(image->pixels);
    decoded = std::move(d);
  }
  recent_.put(key, decoded);
  local.emplace(key, decoded);
  return decoded;
}

Result<std::optional<formats::ImageRgba>> ServiceImagery::loadImage(const geo::TileId& tile) {
  if (peekTile(tile) == Peek::Absent) return std::optional<formats::ImageRgba>();
  const auto r = geo::GeographicTilingScheme::tileRectangle(tile);
  const size_t m = matrixForTile(tile);
  const TileMatrix& matrix = tiling().matrices.at(m);
  const uint32_t n = kTileSizePixels;
  const double west = geo::radiansToDegrees(r.westRadians);
  const double north = geo::radiansToDegrees(r.northRadians);
  const double width = geo::radiansToDegrees(r.widthRadians());
  const double height = geo::radiansToDegrees(r.heightRadians());
  const double worldUnits =
      tiling().crs == TileCrs::Geographic ? 360.0 : 2 * 3.141592653589793 * 6378137.0;
  const auto gridPixelsX = static_cast<int64_t>(matrix.columns * matrix.tileWidth);
  const auto gridPixelsY = static_cast<int64_t>(matrix.rows * matrix.tileHeight);
  // The grid spans the whole world east-west: pixels wrap across ±180°.
  const bool wraps = std::fabs(static_cast<double>(gridPixelsX) * matrix.unitsPerPixel -
                               worldUnits) < matrix.unitsPerPixel;

  // Source pixel coordinates (centres at .0) per output column and row.
  std::vector<double> gx(n), gy(n);
  std::vector<bool> rowInside(n);
  for (uint32_t c = 0; c < n; ++c) {
    const double lon = west + width * c / (n - 1);
    gx[c] = (toCrs(tiling().crs, lon, 0)->first - matrix.originX) / matrix.unitsPerPixel - 0.5;
  }
  for (uint32_t row = 0; row < n; ++row) {
    const double lat = north - height * row / (n - 1);
    const auto xy = toCrs(tiling().crs, 0, lat);
    rowInside[row] = xy.has_value();
    gy[row] = xy ? (matrix.originY - xy->second) / matrix.unitsPerPixel - 0.5 : 0;
  }

  formats::ImageRgba out{static_cast<int>(n), static_cast<int>(n),
                         std::vector<uint8_t>(size_t{n} * n * 4, 0)};
  std::map<Key, std::shared_ptr<const Decoded>> local;
  bool any = false;
  for (uint32_t row = 0; row < n; ++row) {
    if (!rowInside[row]) continue;
    const double fy = std::floor(gy[row]);
    const double ty = gy[row] - fy;
    for (uint32_t c = 0; c < n; ++c) {
      const double fx = std::floor(gx[c]);
      const double tx = gx[c] - fx;
      double sum[4] = {0, 0, 0, 0};  // premultiplied colour and alpha
      for (int dy = 0; dy < 2; ++dy) {
        int64_t py = static_cast<int64_t>(fy) + dy;
        py = std::clamp<int64_t>(py, 0, gridPixelsY - 1);
        if (gy[row] < -0.5 || gy[row] > static_cast<double>(gridPixelsY) - 0.5) continue;
        for (int dx = 0; dx < 2; ++dx) {
          const double weight = (dx ? tx : 1 - tx) * (dy ? ty : 1 - ty);
          if (weight <= 0) continue;
          int64_t px = static_cast<int64_t>(fx) + dx;
          if (wraps) {
            px = ((px % gridPixelsX) + gridPixelsX) % gridPixelsX;
          } else {
            if (gx[c] < -0.5 || gx[c] > static_cast<double>(gridPixelsX) - 0.5) continue;
            px = std::clamp<int64_t>(px, 0, gridPixelsX - 1);
          }
          const Key key{m, static_cast<uint64_t>(px) / matrix.tileWidth,
                        static_cast<uint64_t>(py) / matrix.tileHeight};
          auto source = sourceTile(key, local);
          if (!source) return Error{source.error()};
          if (!*source) continue;
          const Decoded& d = **source;
          // A tile of another size than the matrix says is read at its own scale.
          const uint64_t sx =
              (static_cast<uint64_t>(px) % matrix.tileWidth) * d.width / matrix.tileWidth;
          const uint64_t sy =
              (static_cast<uint64_t>(py) % matrix.tileHeight) * d.height / matrix.tileHeight;
          const uint8_t* p = &d.rgba[(sy * d.width + sx) * 4];
          const double a = p[3] / 255.0 * weight;
          sum[0] += p[0] * a;
          sum[1] += p[1] * a;
          sum[2] += p[2] * a;
          sum[3] += a;
        }
      }
      if (sum[3] <= 0) continue;
      uint8_t* o = &out.pixels[(size_t{row} * n + c) * 4];
      for (int k = 0; k < 3; ++k)
        o[k] = static_cast<uint8_t>(std::clamp(std::lround(sum[k] / sum[3]), 0L, 255L));
      o[3] = static_cast<uint8_t>(std::clamp(std::lround(sum[3] * 255), 0L, 255L));
      any = true;
    }
  }
  if (!any) return std::optional<formats::ImageRgba>();
  return std::optional<formats::ImageRgba>(std::move(out));
}

}  // namespace globe::services
