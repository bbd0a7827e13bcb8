#include "services/xyz_elevation_source.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <numbers>

#include "formats/image_io.hpp"
#include "geo/tiling_scheme.hpp"
#include "geo/web_mercator.hpp"
#include "services/pixel_tin.hpp"
#include "services/recent_items.hpp"
#include "services/tile_matrix.hpp"
#include "services/tin_sampling.hpp"
#include "services/url_reader.hpp"
#include "services/url_template.hpp"

namespace globe::services {
namespace {

constexpr size_t kMaxElevationTileBytes = size_t{8} << 20;
constexpr size_t kDecodedElevationTiles = 64;
// How many zooms finer than a block's own its samples may come from (4^k tiles a block).
constexpr uint32_t kFinerZoomsBelowMin = 2;
// A Mercator pixel is 1/cos(latitude) times shorter north-south than east-west: the tree goes up
// to this many levels deeper towards the poles so that blocks stay as fine as the pixels
// (log2(1/cos 85.05°) = 3.5).
constexpr uint32_t kPolewardLevels = 4;
// And one level finer than the pixels everywhere: the drawn triangles between the vertices then
// follow the pixels' bilinear surface closely, cliffs included (the Grand Canyon's z12 walls:
// 95th percentile 14.2 m off with vertices a pixel wide at the equator, 3.4 m as fine as the
// pixels at their latitude, 1.9 m one level finer; TerrainServices.TerrariumIsReadToItsPixels).
constexpr uint32_t kOversampleLevels = 1;
// The finest zoom's blocks are drawn as the TIN of their pixels (pixel_tin.hpp), within this
// of the pixels' bilinear surface, where their window holds at most this many pixels (a
// block of the equator's level at 60° reads 66×131; deeper levels there fewer).
constexpr double kPixelTinToleranceMeters = 0.25;
constexpr int64_t kMaxTinPixels = 4 * 65 * 65;

// The levels past the equator's that a tile at these latitudes (radians) needs for its vertex
// step to be no wider than the finest pixels' north-south size there.
uint32_t polewardLevels(double southRadians, double northRadians) {
  const double nearestEquator = southRadians <= 0 && northRadians >= 0
                                    ? 0.0
                                    : std::min(std::fabs(southRadians), std::fabs(northRadians));
  const double levels = std::log2(1 / std::cos(nearestEquator));
  return static_cast<uint32_t>(std::clamp(std::ceil(levels - 1e-9), 0.0, double{kPolewardLevels}));
}

struct MercatorTile {
  uint32_t z, x, y;
  auto operator<=>(const MercatorTile&) const = default;
};

// A decoded tile: heights per pixel (NaN: no data), or absent (404).
struct DecodedTile {
  uint32_t size = 0;
  std::vector<float> heightMeters;
};
using TileMap = std::map<MercatorTile, std::shared_ptr<const DecodedTile>>;

class XyzElevationSource final : public ServiceTerrainSource {
 public:
  XyzElevationSource(const ServiceDescription& d, terrain::SeaSurface sea,
                     ElevationEncoding encoding, std::string pattern,
                     std::vector<std::string> subdomains, uint32_t minZoom, uint32_t maxZoom,
                     uint32_t tileSize, double seaLevelMeters, uint32_t equatorLevel,
                     std::unique_ptr<UrlReader> reader)
      : ServiceTerrainSource(d, sea),
        encoding_(encoding),
        pattern_(std::move(pattern)),
        subdomains_(std::move(subdomains)),
        minZoom_(minZoom),
        maxZoom_(maxZoom),
        tileSize_(tileSize),
        seaLevelMeters_(seaLevelMeters),
        equatorLevel_(equatorLevel),
        reader_(std::move(reader)) {}

  std::string location(const geo::TileId& tile) const override {
    const auto rect = geo::GeographicTilingScheme::tileRectangle(tile);
    const uint32_t z = zoomFor(tile.level);
    const double lon = (rect.westRadians + rect.eastRadians) / 2;
    const double lat = (rect.southRadians + rect.northRadians) / 2;
    const double scale = std::ldexp(1.0, static_cast<int>(z));
    return urlOf({z, static_cast<uint32_t>(std::clamp(mercatorX(lon) * scale, 0.0, scale - 1)),
                  static_cast<uint32_t>(std::clamp(mercatorY(lat) * scale, 0.0, scale - 1))});
  }

 protected:
  // As deep as the blocks' vertices are finer than the finest zoom's pixels there: at the
  // equator one level past the one whose step is a pixel, towards the poles deeper.
  bool publishes(const geo::TileId& tile) const override {
    const auto rect = geo::GeographicTilingScheme::tileRectangle(tile);
    return tile.level <= std::min(manifest().maxLevel(),
                                  equatorLevel_ + kOversampleLevels +
                                      polewardLevels(rect.southRadians, rect.northRadians));
  }

  Result<std::optional<ServiceSamples>> fetchSamples(const geo::TileId& tile) override {
    const uint32_t z = zoomFor(tile.level);
    if (z < minZoom_) return std::optional<ServiceSamples>();  // nothing published that coarse
    const auto rect = geo::GeographicTilingScheme::tileRectangle(tile);
    const int n = static_cast<int>(kServiceVerticesPerSide);
    const int w = terrain::kApronWidth;
    const double scale = std::ldexp(1.0, static_cast<int>(z));
    ServiceSamples s;
    s.heightMeters.resize(ServiceSamples::count());
    s.water.assign(ServiceSamples::count(), 0);
    TileMap tiles;
    bool anyData = false;
    size_t k = 0;
    for (int row = -w; row < n + w; ++row) {
      const double lat = std::clamp(rect.northRadians - row * rect.heightRadians() / (n - 1),
                                    -std::numbers::pi / 2, std::numbers::pi / 2);
      const double py = mercatorY(lat) * scale;  // in tiles
      for (int column = -w; column < n + w; ++column, ++k) {
        const double lon = rect.westRadians + column * rect.widthRadians() / (n - 1);
        const double px = mercatorX(lon) * scale;
        auto h = sample(z, px, py, tiles);
        if (!h) return Error{h.error()};
        s.heightMeters[k] = *h;
        anyData = anyData || std::isfinite(*h);
      }
    }
    if (!anyData) return std::optional<ServiceSamples>();  // the parent's surface
    for (size_t i = 0; i < s.heightMeters.size(); ++i) {
      // Transparent pixels: the producer's sea (Terrain-RGB writes none over water). Where a
      // tile is missing the height stays NaN: the parent's surface.
      if (std::isinf(s.heightMeters[i])) {
        s.heightMeters[i] = 0;
        if (s.water.empty()) s.water.assign(ServiceSamples::count(), 0);
        s.water[i] = 1;
      } else if (s.heightMeters[i] <= seaLevelMeters_) {
        s.water[i] = 1;
      }
    }
    auto tin = pixelTin(tile, z, tiles);
    if (!tin) return Error{tin.error()};
    s.tin = std::move(*tin);
    return std::optional<ServiceSamples>(std::move(s));
  }

 private:
  // The square world's x and y (0..1, y from the north) of a longitude and latitude in radians.
  static double mercatorX(double lon) { return lon / (2 * std::numbers::pi) + 0.5; }
  static double mercatorY(double lat) {
    return geo::webMercatorRowOf(lat * 180 / std::numbers::pi, 0);
  }

  // The Mercator zoom whose pixels are about the block's vertex step at the equator (a
  // 256-pixel tile at zoom z spans 360/2^z degrees; a block at level L 180/2^L over N-1 steps).
  // Blocks a little coarser than the service's first zoom sample that zoom's pixels (a few more
  // tiles each), so a regional tree shows from further away than its first zoom.
  uint32_t zoomFor(uint32_t level) const {
    const double z = level + std::log2(2.0 * (kServiceVerticesPerSide - 1) / tileSize_);
    const auto zoom =
        static_cast<uint32_t>(std::clamp(std::ceil(z - 1e-9), 0.0, static_cast<double>(maxZoom_)));
    return zoom < minZoom_ && minZoom_ - zoom <= kFinerZoomsBelowMin ? minZoom_ : zoom;
  }

  std::string urlOf(const MercatorTile& t) const {
    return expandTileUrl(pattern_, {t.z, t.x, t.y, "", subdomains_});
  }

  // Global pixel (column across ±180° wrapped, row clamped at the poles) of zoom z: nullopt
  // where its tile is missing, NaN where it is transparent.
  Result<std::optional<double>> pixel(uint32_t z, int64_t column, int64_t row, TileMap& tiles) {
    const auto worldPixels = (int64_t{1} << z) * tileSize_;
    column = ((column % worldPixels) + worldPixels) % worldPixels;
    row = std::clamp<int64_t>(row, 0, worldPixels - 1);
    const MercatorTile t{z, static_cast<uint32_t>(column / tileSize_),
                         static_cast<uint32_t>(row / tileSize_)};
    auto decoded = tile(t, tiles);
    if (!decoded) return Error{decoded.error()};
    if (!*decoded) return std::optional<double>();
    const DecodedTile& d = **decoded;
    // A tile of another size than declared is sampled at its own scale.
    const auto c = static_cast<uint32_t>((column % tileSize_) * d.size / tileSize_);
    const auto r = static_cast<uint32_t>((row % tileSize_) * d.size / tileSize_);
    return std::optional<double>(d.heightMeters[static_cast<size_t>(r) * d.size + c]);
  }

  // Bilinear between pixel centres at (px, py) in tile units; NaN where a tile is missing,
  // +inf where every pixel around is transparent.
  Result<double> sample(uint32_t z, double px, double py, TileMap& tiles) {
    const double gx = px * tileSize_ - 0.5, gy = py * tileSize_ - 0.5;  // global pixels
    const double fx = std::floor(gx), fy = std::floor(gy);
    const double tx = gx - fx, ty = gy - fy;
    double total = 0, weights = 0;
    for (int dy = 0; dy < 2; ++dy) {
      for (int dx = 0; dx < 2; ++dx) {
        auto h = pixel(z, static_cast<int64_t>(fx) + dx, static_cast<int64_t>(fy) + dy, tiles);
        if (!h) return Error{h.error()};
        if (!*h) return std::numeric_limits<double>::quiet_NaN();  // a missing tile
        if (std::isnan(**h)) continue;
        const double weight = (dx ? tx : 1 - tx) * (dy ? ty : 1 - ty);
        total += weight * **h;
        weights += weight;
      }
    }
    // All four transparent: the producer's sea (+inf); beside it, the pixels that have data.
    if (weights <= 0) return std::numeric_limits<double>::infinity();
    return total / weights;
  }

  // The surface a pixel shows, as the grid's samples take it: water (transparent, or at or
  // below the sea level) at its surface (0 m, or its floor with SeaFloor).
  double surfaceOf(double pixel) const {
    if (std::isnan(pixel)) return 0;
    if (pixel > seaLevelMeters_) return pixel;
    return sea() == terrain::SeaSurface::Water ? 0 : std::min(pixel, 0.0);
  }

  // The block as the TIN of its pixels' surface (pixel_tin.hpp) within the Mercator band, at
  // the finest zoom, where not too many pixels and none of their tiles missing; else null (the
  // grid, which at the data's edge goes down to the parent's surface).
  Result<std::shared_ptr<const terrain::TinTile>> pixelTin(const geo::TileId& tile, uint32_t z,
                                                           TileMap& tiles) {
    const auto rect = geo::GeographicTilingScheme::tileRectangle(tile);
    const double limit = kWebMercatorMaxLatitudeDegrees * std::numbers::pi / 180;
    if (z != maxZoom_ || rect.northRadians > limit || rect.southRadians < -limit) {
      return std::shared_ptr<const terrain::TinTile>();
    }
    PixelWindow window;
    window.worldPixels = std::ldexp(static_cast<double>(tileSize_), static_cast<int>(z));
    const PixelRange range = pixelRangeOf(rect, window.worldPixels);
    window.firstColumn = range.firstColumn;
    window.firstRow = range.firstRow;
    window.columns = range.lastColumn - range.firstColumn + 1;
    window.rows = range.lastRow - range.firstRow + 1;
    if (window.columns * window.rows > kMaxTinPixels)
      return std::shared_ptr<const terrain::TinTile>();
    for (int64_t row = range.firstRow; row <= range.lastRow; ++row) {
      for (int64_t column = range.firstColumn; column <= range.lastColumn; ++column) {
        auto h = pixel(z, column, row, tiles);
        if (!h) return Error{h.error()};
        if (!*h) return std::shared_ptr<const terrain::TinTile>();  // the data's edge
        window.heightMeters.push_back(surfaceOf(**h));
      }
    }
    return buildPixelTin(rect, window, kPixelTinToleranceMeters, location(tile));
  }

  Result<std::shared_ptr<const DecodedTile>> tile(const MercatorTile& t, TileMap& local) {
    if (auto it = local.find(t); it != local.end()) return it->second;
    std::optional<std::shared_ptr<const DecodedTile>> kept = recent_.find(t);
    std::shared_ptr<const DecodedTile> decoded = kept ? *kept : nullptr;
    if (!kept) {
      const std::string url = urlOf(t);
      auto bytes = reader_->read(url, kMaxElevationTileBytes);
      if (!bytes) return Error{bytes.error()};
      if (*bytes) {
        auto image = formats::decodeImageRgba(**bytes, url);
        if (!image) return Error{image.error()};
        if (image->widthPixels != image->heightPixels || image->widthPixels <= 0) {
          return makeError(url + ": an elevation tile of " + std::to_string(image->widthPixels) +
                           "×" + std::to_string(image->heightPixels) + " pixels (square expected)");
        }
        auto d = std::make_shared<DecodedTile>();
        d->size = static_cast<uint32_t>(image->widthPixels);
        d->heightMeters.resize(size_t{d->size} * d->size);
        for (size_t p = 0; p < d->heightMeters.size(); ++p) {
          d->heightMeters[p] =
              static_cast<float>(decodeElevationPixel(encoding_, &image->pixels[4 * p]));
        }
        decoded = std::move(d);
      }
      recent_.put(t, decoded);
    }
    local.emplace(t, decoded);
    return decoded;
  }

  ElevationEncoding encoding_;
  std::string pattern_;
  std::vector<std::string> subdomains_;
  uint32_t minZoom_, maxZoom_, tileSize_;
  double seaLevelMeters_;  // samples at or below are water; -inf: none
  uint32_t equatorLevel_;  // the level whose vertex step is the finest zoom's pixel
  std::unique_ptr<UrlReader> reader_;
  // Decoded tiles (null: the service has none there).
  RecentItems<MercatorTile, std::shared_ptr<const DecodedTile>> recent_{kDecodedElevationTiles};
};

}  // namespace

double decodeElevationPixel(ElevationEncoding encoding, const uint8_t rgba[4]) {
  if (rgba[3] == 0) return std::numeric_limits<double>::quiet_NaN();
  if (encoding == ElevationEncoding::Terrarium) {
    return rgba[0] * 256.0 + rgba[1] + rgba[2] / 256.0 - 32768.0;
  }
  return -10000.0 + (rgba[0] * 65536.0 + rgba[1] * 256.0 + rgba[2]) * 0.1;
}

Result<std::unique_ptr<ServiceTerrainSource>> openXyzElevationSource(
    ElevationEncoding encoding, const std::string& spec, terrain::SeaSurface sea,
    std::shared_ptr<transport::Network> network) {
  const char* kind = encoding == ElevationEncoding::Terrarium ? "terrarium" : "terrain-rgb";
  std::string pattern = spec;
  auto options = takeQueryOptions(
      pattern, {"maxzoom", "minzoom", "subdomains", "tilesize", "sea", "attribution"});
  auto problem = [&](const std::string& what) {
    return makeError(std::string(kind) + ":" + spec + ": " + what);
  };
  auto xyz =
      xyzTemplateOptions(pattern, options, encoding == ElevationEncoding::Terrarium ? 15 : 14);
  if (!xyz) return problem(xyz.error());
  double seaLevelMeters = 0;
  if (auto level = options.find("sea"); level != options.end()) {
    if (level->second == "none") {
      seaLevelMeters = -std::numeric_limits<double>::infinity();
    } else {
      char* end = nullptr;
      seaLevelMeters = std::strtod(level->second.c_str(), &end);
      if (level->second.empty() || *end != '\0' || !(std::fabs(seaLevelMeters) <= 1000)) {
        return problem("sea=" + level->second + ": expected metres (-1000..1000) or none");
      }
    }
  }
  ServiceDescription d;
  d.location = std::string(kind) + ":" + spec;
  d.attribution = options.count("attribution") ? options["attribution"] : "";
  d.format = kind;
  // The level whose blocks sample the finest zoom's pixels one to one at the equator, and the
  // deepest any tile may need towards the poles.
  const double levels =
      xyz->maxZoom - std::log2(2.0 * (kServiceVerticesPerSide - 1) / xyz->tileSize);
  const auto equatorLevel =
      static_cast<uint32_t>(std::clamp(std::ceil(levels - 1e-9), 0.0, double{geo::kMaxLevel}));
  d.maxLevel = std::min(equatorLevel + kOversampleLevels + kPolewardLevels, geo::kMaxLevel);
  d.stepDegrees = 360.0 / (std::ldexp(1.0, static_cast<int>(xyz->maxZoom)) * xyz->tileSize);
  d.bounds = {-180, -kWebMercatorMaxLatitudeDegrees, 180, kWebMercatorMaxLatitudeDegrees};
  auto reader = std::make_unique<UrlReader>(network, "image/png,image/*;q=0.9");
  d.remote = reader->remote(pattern);
  return std::unique_ptr<ServiceTerrainSource>(std::make_unique<XyzElevationSource>(
      d, sea, encoding, pattern, xyz->subdomains, xyz->minZoom, xyz->maxZoom, xyz->tileSize,
      seaLevelMeters, equatorLevel, std::move(reader)));
}

}  // namespace globe::services
