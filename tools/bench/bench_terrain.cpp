// The bench's pyramid access, its Fuji-centred tile arrays and its camera queries.
#include "tools/bench/bench_terrain.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "collision/exact_surface.hpp"
#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "tests/support/build_paths.hpp"
#include "tiling/tiler.hpp"

namespace globe::bench {
namespace {

using Scheme = geo::GeographicTilingScheme;

// The most nearly square width x height = tiles with width >= height.
std::pair<uint32_t, uint32_t> rectangleOf(uint32_t tiles) {
  auto height = static_cast<uint32_t>(std::sqrt(static_cast<double>(tiles)));
  while (height > 1 && tiles % height != 0) --height;
  return {tiles / height, height};
}

double surfaceHeight(const terrain::RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                     double longitude, double latitude) {
  const auto surface = collision::exactSurfaceHeight(array, ellipsoid, longitude, latitude);
  return surface ? surface->heightMeters : 0.0;
}

CameraQuery queryAt(const geo::Ellipsoid& ellipsoid, double longitude, double latitude,
                    double surfaceMeters, double aboveMeters) {
  CameraQuery query;
  query.longitudeRadians = longitude;
  query.latitudeRadians = latitude;
  query.heightMeters = surfaceMeters + aboveMeters;
  query.aboveSurfaceMeters = aboveMeters;
  query.ecefMeters = geo::cartographicToEcef(ellipsoid, {longitude, latitude, query.heightMeters});
  return query;
}

}  // namespace

Result<std::unique_ptr<Pyramid>> Pyramid::open(const std::filesystem::path& directory) {
  std::filesystem::path dir = directory;
  std::filesystem::path scratch;
  if (dir.empty()) {
    scratch =
        std::filesystem::temp_directory_path() / ("globe-bench-" + std::to_string(::getpid()));
    std::error_code ignored;
    std::filesystem::remove_all(scratch, ignored);
    const std::string dem = std::string(GLOBE_SOURCE_DIR) + "/data/dem/";
    tiling::TilerOptions options;
    options.inputs = {dem + "ETOPO20.DEM", dem + "W002N52.DEM", dem + "E138N35_FUJI.DEM"};
    options.outputDir = scratch / "pyramid";
    auto report = tiling::runTiler(options);
    if (!report) {
      std::filesystem::remove_all(scratch, ignored);
      return Error{report.error()};
    }
    dir = options.outputDir;
  }
  auto store = streaming::TileStore::open(dir);
  if (!store) return Error{store.error()};
  return std::unique_ptr<Pyramid>(new Pyramid(std::move(*store), scratch));
}

Pyramid::~Pyramid() {
  store_.reset();
  if (!scratch_.empty()) {
    std::error_code ignored;
    std::filesystem::remove_all(scratch_, ignored);
  }
}

bool Pyramid::has(const geo::TileId& tile) {
  if (!Scheme::isValid(tile)) return false;
  auto entry = store_->entry(tile);
  return entry && entry->has_value();
}

const terrain::HeightBlock& Pyramid::block(const geo::TileId& tile) {
  const auto it = blocks_.find(tile);
  if (it != blocks_.end()) return it->second;
  auto loaded = store_->loadBlock(tile);
  return blocks_.emplace(tile, loaded ? std::move(*loaded) : terrain::HeightBlock{}).first->second;
}

std::vector<geo::TileId> Pyramid::tilesOfLevel(uint32_t level, double westDegrees,
                                               double southDegrees, double eastDegrees,
                                               double northDegrees) {
  const geo::GlobeRectangle area =
      geo::GlobeRectangle::fromDegrees(westDegrees, southDegrees, eastDegrees, northDegrees);
  const auto northWest = Scheme::positionToTile(area.westRadians, area.northRadians, level);
  const auto southEast = Scheme::positionToTile(area.eastRadians, area.southRadians, level);
  std::vector<geo::TileId> tiles;
  if (!northWest || !southEast) return tiles;
  // One tile of margin: the closed intersection test decides.
  const uint32_t x0 = northWest->x > 0 ? northWest->x - 1 : 0;
  const uint32_t y0 = northWest->y > 0 ? northWest->y - 1 : 0;
  const uint32_t x1 = std::min(southEast->x + 1, Scheme::tilesX(level) - 1);
  const uint32_t y1 = std::min(southEast->y + 1, Scheme::tilesY(level) - 1);
  for (uint32_t y = y0; y <= y1; ++y) {
    for (uint32_t x = x0; x <= x1; ++x) {
      const geo::TileId tile{level, x, y};
      if (Scheme::tileRectangle(tile).intersects(area) && has(tile)) tiles.push_back(tile);
    }
  }
  return tiles;
}

Result<std::unique_ptr<BenchArray>> makeBenchArray(Pyramid& pyramid, uint32_t tiles) {
  if (tiles == 0) return Error{"an array needs at least one tile"};
  if (pyramid.manifest().maxLevel() < kBenchLevel) {
    return Error{"the pyramid has no level " + std::to_string(kBenchLevel)};
  }
  // The Fuji tiles of the bench level: a full rectangle of the pyramid.
  const formats::BoundsDegrees b = pyramid.manifest().levels[kBenchLevel].bounds;
  const std::vector<geo::TileId> fuji =
      pyramid.tilesOfLevel(kBenchLevel, b.west, b.south, b.east, b.north);
  if (fuji.empty()) return Error{"no tiles at the bench level"};
  uint32_t fx0 = UINT32_MAX, fy0 = UINT32_MAX, fx1 = 0, fy1 = 0;
  for (const geo::TileId& id : fuji) {
    fx0 = std::min(fx0, id.x), fy0 = std::min(fy0, id.y);
    fx1 = std::max(fx1, id.x), fy1 = std::max(fy1, id.y);
  }
  const uint32_t fuW = fx1 - fx0 + 1, fuH = fy1 - fy0 + 1;
  if (fuji.size() != size_t{fuW} * fuH) return Error{"the Fuji tiles are not a rectangle"};

  const auto summit =
      Scheme::positionToTile(geo::degreesToRadians(kFujiSummitLongitudeDegrees),
                             geo::degreesToRadians(kFujiSummitLatitudeDegrees), kBenchLevel);
  auto result = std::make_unique<BenchArray>();
  const auto [width, height] = rectangleOf(tiles);
  result->width = width;
  result->height = height;
  const uint32_t x0 = summit->x - (width - 1) / 2;
  const uint32_t y0 = summit->y - (height - 1) / 2;
  const geo::GlobeRectangle first = Scheme::tileRectangle({kBenchLevel, x0, y0});
  const geo::GlobeRectangle last =
      Scheme::tileRectangle({kBenchLevel, x0 + width - 1, y0 + height - 1});
  result->bounds = {first.westRadians, last.southRadians, last.eastRadians, first.northRadians};

  auto wrap = [](uint32_t value, uint32_t origin, uint32_t period) {
    const int64_t offset = (static_cast<int64_t>(value) - origin) % period;
    return origin + static_cast<uint32_t>(offset < 0 ? offset + period : offset);
  };
  result->blocks.reserve(tiles);
  std::vector<terrain::ArrayTile> arrayTiles;
  arrayTiles.reserve(tiles);
  for (uint32_t y = y0; y < y0 + height; ++y) {
    for (uint32_t x = x0; x < x0 + width; ++x) {
      const geo::TileId source{kBenchLevel, wrap(x, fx0, fuW), wrap(y, fy0, fuH)};
      if (source.x == x && source.y == y) ++result->realPositionTiles;
      result->blocks.push_back(pyramid.block(source));
      if (result->blocks.back().heights.empty()) return Error{"a block could not be read"};
      arrayTiles.push_back(terrain::makeArrayTile({kBenchLevel, x, y}, result->blocks.back()));
    }
  }
  result->array.assign(std::move(arrayTiles));
  if (result->array.rejectedTileCount() != 0) return Error{"tiles were rejected"};
  return result;
}

geo::GlobeRectangle flightArea() {
  const auto summit =
      Scheme::positionToTile(geo::degreesToRadians(kFujiSummitLongitudeDegrees),
                             geo::degreesToRadians(kFujiSummitLatitudeDegrees), kBenchLevel);
  const geo::GlobeRectangle first = Scheme::tileRectangle({kBenchLevel, summit->x - 2, summit->y});
  const geo::GlobeRectangle last =
      Scheme::tileRectangle({kBenchLevel, summit->x + 2, summit->y + 1});
  return {first.westRadians, last.southRadians, last.eastRadians, first.northRadians};
}

std::vector<CameraQuery> flightPath(const terrain::RenderingTileArray& array,
                                    const geo::GlobeRectangle& area,
                                    const geo::Ellipsoid& ellipsoid, size_t frames, uint64_t seed) {
  constexpr double kSpeedMetersPerSecond = 50.0;
  constexpr double kFrameSeconds = 1.0 / 60.0;
  constexpr double kMarginMeters = 50.0;
  constexpr double kAglPeriodSeconds = 10.0;
  const double radius = ellipsoid.semiMajorAxisMeters;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> turn(0.0, 0.03), drift(0.0, 0.01);
  double lon = area.westRadians + 0.3 * area.widthRadians();
  double lat = area.southRadians + 0.5 * area.heightRadians();
  double heading = 0.7;  // radians from north, clockwise
  double phase = 0.0;
  std::vector<CameraQuery> path;
  path.reserve(frames);
  for (size_t frame = 0; frame < frames; ++frame) {
    const double marginLat = kMarginMeters / radius;
    const double marginLon = kMarginMeters / (radius * std::cos(lat));
    const double step = kSpeedMetersPerSecond * kFrameSeconds;
    heading += turn(rng);
    lat += step * std::cos(heading) / radius;
    lon += step * std::sin(heading) / (radius * std::cos(lat));
    if (lon < area.westRadians + marginLon || lon > area.eastRadians - marginLon) {
      heading = -heading;
      lon = std::clamp(lon, area.westRadians + marginLon, area.eastRadians - marginLon);
    }
    if (lat < area.southRadians + marginLat || lat > area.northRadians - marginLat) {
      heading = std::numbers::pi - heading;
      lat = std::clamp(lat, area.southRadians + marginLat, area.northRadians - marginLat);
    }
    phase += 2.0 * std::numbers::pi * kFrameSeconds / kAglPeriodSeconds + drift(rng);
    const double above = 160.0 + 140.0 * std::sin(phase);
    path.push_back(queryAt(ellipsoid, lon, lat, surfaceHeight(array, ellipsoid, lon, lat), above));
  }
  return path;
}

std::vector<CameraQuery> randomQueries(const terrain::RenderingTileArray& array,
                                       const geo::GlobeRectangle& rectangle,
                                       const geo::Ellipsoid& ellipsoid, size_t count,
                                       uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0), above(20.0, 300.0);
  std::vector<CameraQuery> queries;
  queries.reserve(count);
  for (size_t k = 0; k < count; ++k) {
    const double lon = rectangle.westRadians + unit(rng) * rectangle.widthRadians();
    const double lat = rectangle.southRadians + unit(rng) * rectangle.heightRadians();
    queries.push_back(
        queryAt(ellipsoid, lon, lat, surfaceHeight(array, ellipsoid, lon, lat), above(rng)));
  }
  return queries;
}

}  // namespace globe::bench
