#include "apps/globe/query_command.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "camera/path_checks.hpp"
#include "geo/cartographic.hpp"
#include "geo/tiling_scheme.hpp"
#include "services/terrain_services.hpp"
#include "tiles3d/tileset.hpp"
#include "tiles3d/tileset_surface.hpp"

namespace globe::app {
namespace {

constexpr size_t kMaxCachedBlocks = 4096;

std::optional<double> parseNumber(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r')) {
    text.remove_suffix(1);
  }
  return camera::parseDecimal(text);  // 1e999 reads as inf, refused below as not finite
}

// "lon,lat" → radians, or the reason the line is rejected.
Result<std::pair<double, double>> parseLine(const std::string& line) {
  const auto comma = line.find(',');
  if (comma == std::string::npos) return makeError("expected lon,lat in degrees");
  const auto lon = parseNumber(std::string_view(line).substr(0, comma));
  const auto lat = parseNumber(std::string_view(line).substr(comma + 1));
  if (!lon || !lat) return makeError("expected lon,lat in degrees");
  if (!std::isfinite(*lon)) return makeError("longitude is not a finite number");
  if (!std::isfinite(*lat)) return makeError("latitude is not a finite number");
  if (*lat < -90 || *lat > 90) return makeError("latitude must be within -90..90");
  if (*lon < -540 || *lon > 540) return makeError("longitude must be within -540..540");
  return std::pair{geo::wrapLongitudeRadians(geo::degreesToRadians(*lon)),
                   geo::degreesToRadians(*lat)};
}

// Each tileset's surface, its warnings said once on `errors`.
Result<std::vector<tiles3d::TilesetSurface>> loadTilesets(const QueryOptions& options,
                                                          const geo::Ellipsoid& ellipsoid,
                                                          std::FILE* errors) {
  std::vector<tiles3d::TilesetSurface> surfaces;
  for (const auto& path : options.tilesets) {
    auto tileset = tiles3d::openTileset(path, options.network.get(), ellipsoid);
    if (!tileset) return Error{tileset.error()};
    auto surface = tiles3d::TilesetSurface::load(*tileset, ellipsoid);
    if (!surface) return Error{surface.error()};
    for (const std::string& w : surface->warnings())
      std::fprintf(errors, "globe query: %s\n", w.c_str());
    surfaces.push_back(std::move(*surface));
  }
  return surfaces;
}

}  // namespace

Result<QueryReport> runQuery(const QueryOptions& options, std::istream& in, std::FILE* out,
                             std::FILE* errors) {
  auto store = services::openTerrainSource(options.pyramid, options.sea, options.network);
  if (!store) return Error{store.error()};
  const uint32_t maxLevel = (*store)->manifest().maxLevel();
  if (options.level && *options.level > maxLevel) {
    return makeError("--level " + std::to_string(*options.level) +
                     ": the pyramid's levels are 0.." + std::to_string(maxLevel));
  }
  const geo::Ellipsoid ellipsoid = geo::ellipsoidFor(options.globeModel);
  auto tilesets = loadTilesets(options, ellipsoid, errors);
  if (!tilesets) return Error{tilesets.error()};
  std::map<geo::TileId, terrain::HeightBlock> blocks;
  QueryReport report;
  std::string line;
  for (uint64_t number = 1; std::getline(in, line); ++number) {
    if (line.empty() || line == "\r") continue;
    auto position = parseLine(line);
    std::optional<geo::TileId> tile;
    std::string problem = position ? "" : position.error();
    // The finest level the pyramid has at this point (every level is loadable from disk).
    for (uint32_t level = options.level.value_or(maxLevel) + 1; position && level-- > 0;) {
      const auto candidate =
          geo::GeographicTilingScheme::positionToTile(position->first, position->second, level);
      auto entry = candidate ? (*store)->summary(*candidate)
                             : Result<std::optional<terrain::TileSummary>>(std::nullopt);
      if (!entry) return Error{entry.error()};
      if (*entry) {
        tile = candidate;
        break;
      }
      if (options.level) break;
    }
    if (position && !tile) problem = "the pyramid has no tile there at the requested level";
    if (!problem.empty()) {
      std::fprintf(errors, "globe query: line %llu: '%s': %s\n",
                   static_cast<unsigned long long>(number), line.c_str(), problem.c_str());
      ++report.rejected;
      continue;
    }
    auto found = blocks.end();
    for (;;) {
      found = blocks.find(*tile);
      if (found == blocks.end()) {
        if (blocks.size() >= kMaxCachedBlocks) blocks.clear();
        auto block = (*store)->loadBlock(*tile);
        if (!block) return Error{block.error()};
        found = blocks.emplace(*tile, std::move(*block)).first;
      }
      // A service's tiles may tell of finer ones (Cesium's metadata availability): deeper then.
      if (options.level || tile->level >= maxLevel) break;
      const auto finer = geo::GeographicTilingScheme::positionToTile(
          position->first, position->second, tile->level + 1);
      auto finerSummary = finer ? (*store)->summary(*finer)
                                : Result<std::optional<terrain::TileSummary>>(std::nullopt);
      if (!finerSummary) return Error{finerSummary.error()};
      if (!*finerSummary) break;
      tile = finer;
    }
    terrain::RenderingTileArray array;
    array.assign({terrain::makeArrayTile(*tile, found->second)});
    const auto sample =
        collision::sampleHeight(array, ellipsoid, position->first, position->second, options.mode);
    if (!sample) return makeError("internal: no height in the tile that contains the point");
    double heightMeters = sample->heightMeters;
    for (const auto& tileset : *tilesets) {
      heightMeters = std::max(
          heightMeters, tileset.heightAt(position->first, position->second).value_or(heightMeters));
    }
    std::fprintf(out, "%.9g,%.9g,%u,%.3f\n", geo::radiansToDegrees(position->first),
                 geo::radiansToDegrees(position->second), sample->level, heightMeters);
    ++report.answered;
  }
  return report;
}

}  // namespace globe::app
