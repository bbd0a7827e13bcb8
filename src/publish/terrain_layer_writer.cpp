#include "publish/terrain_layer_writer.hpp"

#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <span>
#include <system_error>
#include <utility>

#include "core/crc32.hpp"
#include "geo/tiling_scheme.hpp"

namespace globe::publish {
namespace {

// `available` for one level: runs of present tiles along each TMS row, runs of equal extent on
// consecutive rows merged into one rectangle.
nlohmann::json availableRanges(const std::set<std::pair<uint32_t, uint32_t>>& rowColumn) {
  std::map<std::pair<uint32_t, uint32_t>, std::vector<uint32_t>> rowsOfRun;  // (x0, x1) → rows
  auto it = rowColumn.begin();
  while (it != rowColumn.end()) {
    const uint32_t row = it->first;
    const uint32_t start = it->second;
    uint32_t end = start;
    ++it;
    while (it != rowColumn.end() && it->first == row && it->second == end + 1) {
      end = it->second;
      ++it;
    }
    rowsOfRun[{start, end}].push_back(row);
  }
  nlohmann::json ranges = nlohmann::json::array();
  for (const auto& [run, rows] : rowsOfRun) {
    size_t k = 0;
    while (k < rows.size()) {
      size_t last = k;
      while (last + 1 < rows.size() && rows[last + 1] == rows[last] + 1) ++last;
      ranges.push_back(
          {{"startX", run.first}, {"startY", rows[k]}, {"endX", run.second}, {"endY", rows[last]}});
      k = last + 1;
    }
  }
  return ranges;
}

// Per level, the (TMS row, column) of every DIR/z/x/y.terrain.
std::vector<std::set<std::pair<uint32_t, uint32_t>>> presentTiles(
    const std::filesystem::path& outDir) {
  std::vector<std::set<std::pair<uint32_t, uint32_t>>> present;
  std::error_code walking;
  for (auto it = std::filesystem::recursive_directory_iterator(outDir, walking);
       !walking && it != std::filesystem::recursive_directory_iterator(); it.increment(walking)) {
    const std::filesystem::path& path = it->path();
    if (path.extension() != ".terrain" || it.depth() != 2) continue;
    try {
      const auto level =
          static_cast<uint32_t>(std::stoul(path.parent_path().parent_path().filename()));
      const auto x = static_cast<uint32_t>(std::stoul(path.parent_path().filename()));
      const auto y = static_cast<uint32_t>(std::stoul(path.stem()));
      if (level > geo::kMaxLevel) continue;
      if (present.size() <= level) present.resize(level + 1);
      present[level].insert({y, x});
    } catch (const std::exception&) {
      continue;  // not a tile of ours
    }
  }
  return present;
}

}  // namespace

std::vector<geo::TileId> candidateTiles(const formats::PyramidManifest& manifest, uint32_t level,
                                        const ExportRegion& region) {
  std::vector<geo::TileId> tiles;
  if (level >= manifest.levels.size()) return tiles;
  const uint32_t perSide = manifest.packTilesPerSide;
  const double tileDegrees = 180.0 / std::ldexp(1.0, static_cast<int>(level));
  const auto column = [&](double lon) { return std::floor((lon + 180.0) / tileDegrees); };
  const auto row = [&](double lat) { return std::floor((90.0 - lat) / tileDegrees); };
  const double x0 = column(region.westDegrees), x1 = column(region.eastDegrees);
  const double y0 = row(region.northDegrees), y1 = row(region.southDegrees);
  for (const formats::PackId& pack : manifest.levels[level].packs) {
    for (uint32_t dy = 0; dy < perSide; ++dy) {
      for (uint32_t dx = 0; dx < perSide; ++dx) {
        const geo::TileId tile{level, pack.x * perSide + dx, pack.y * perSide + dy};
        if (tile.x < x0 || tile.x > x1 || tile.y < y0 || tile.y > y1) continue;
        tiles.push_back(tile);
      }
    }
  }
  return tiles;
}

uint32_t tmsRow(const geo::TileId& tile) { return (1U << tile.level) - 1 - tile.y; }

std::filesystem::path terrainTilePath(const std::filesystem::path& outDir,
                                      const geo::TileId& tile) {
  return outDir / std::to_string(tile.level) / std::to_string(tile.x) /
         (std::to_string(tmsRow(tile)) + ".terrain");
}

std::string treeVersion(const formats::PyramidManifest& manifest, int exporterRevision,
                        std::string_view exporter) {
  const std::string made =
      formats::manifestToJson(manifest) + std::string(exporter) + std::to_string(exporterRevision);
  char hex[16];
  std::snprintf(hex, sizeof hex, "%08x",
                core::crc32(std::as_bytes(std::span(made.data(), made.size()))));
  return std::string("1.0.0-") + hex;
}

Result<void> writeTerrainLayerJson(const std::filesystem::path& outDir, const std::string& format,
                                   const std::string& version,
                                   const streaming::TerrainSource& source,
                                   const std::vector<std::string>& extensions) {
  // What the tree holds, this run's tiles and earlier runs' (another region, other levels).
  const auto present = presentTiles(outDir);
  nlohmann::json available = nlohmann::json::array();
  for (const auto& level : present) available.push_back(availableRanges(level));
  nlohmann::json layer = {{"tilejson", "2.1.0"},
                          {"name", outDir.filename().string()},
                          {"description", "Exported by globe-tiler from " + source.location()},
                          {"version", version},
                          {"format", format},
                          {"scheme", "tms"},
                          {"tiles", {"{z}/{x}/{y}.terrain?v={version}"}},
                          {"projection", "EPSG:4326"},
                          {"bounds", {-180, -90, 180, 90}},
                          {"minzoom", 0},
                          {"maxzoom", present.empty() ? 0 : present.size() - 1},
                          {"available", available},
                          {"attribution", source.attribution()}};
  if (!extensions.empty()) layer["extensions"] = extensions;
  const std::string text = layer.dump(1);
  const std::vector<std::byte> bytes(reinterpret_cast<const std::byte*>(text.data()),
                                     reinterpret_cast<const std::byte*>(text.data()) + text.size());
  std::error_code error;
  std::filesystem::create_directories(outDir, error);
  return writeFileReplacing(outDir / "layer.json", bytes);
}

}  // namespace globe::publish
