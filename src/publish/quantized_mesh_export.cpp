#include "publish/quantized_mesh_export.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "core/crc32.hpp"
#include "formats/deflate_bytes.hpp"
#include "formats/pyramid_manifest.hpp"
#include "formats/pack_format.hpp"
#include "geo/tiling_scheme.hpp"
#include "publish/block_mesh.hpp"
#include "publish/pyramid_surface.hpp"
#include "terrain/block_grid.hpp"

namespace globe::publish {
namespace {

// Vertices per side of every tile: CesiumJS (and globe's reader) estimate a quantized-mesh
// tile's geometric error as a 65×65 heightmap's, so a coarser grid would be refined too little.
constexpr uint32_t kGridVertices = 65;

// Tiles of the level whose rectangle meets the region (degrees), inside the packs it lists.
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

// The pyramid's exact surface at the tile's G×G grid, from its finest tile of level <= level.
Result<std::vector<double>> gridHeights(PyramidSurface& surface, const geo::TileId& tile,
                                        uint32_t level) {
  const terrain::BlockGrid grid{tile, kGridVertices};
  std::vector<double> heights;
  heights.reserve(size_t{kGridVertices} * kGridVertices);
  for (uint32_t row = 0; row < kGridVertices; ++row) {
    const double lat = grid.latitudeDegrees(row) * std::numbers::pi / 180;
    for (uint32_t column = 0; column < kGridVertices; ++column) {
      auto h =
          surface.heightMeters(grid.longitudeDegrees(column) * std::numbers::pi / 180, lat, level);
      if (!h) return Error{h.error()};
      heights.push_back(*h);
    }
  }
  return heights;
}

// The tiles' version, in their URLs ({version}): what they are made from and how, so that a
// client may keep a tile it has as long as the version is the same (tiles of a re-tiled
// pyramid, or made by another exporter revision, get new URLs).
std::string treeVersion(const formats::PyramidManifest& manifest) {
  constexpr int kExporterRevision = 1;
  const std::string made = formats::manifestToJson(manifest) + std::to_string(kExporterRevision);
  char hex[16];
  std::snprintf(hex, sizeof hex, "%08x",
                core::crc32(std::as_bytes(std::span(made.data(), made.size()))));
  return std::string("1.0.0-") + hex;
}

uint32_t tmsRow(const geo::TileId& tile) { return (1U << tile.level) - 1 - tile.y; }

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

}  // namespace

Result<ExportReport> exportQuantizedMesh(streaming::TerrainSource& source,
                                         const ExportRegion& region,
                                         const std::filesystem::path& outDir,
                                         const geo::Ellipsoid& ellipsoid) {
  const formats::PyramidManifest& manifest = source.manifest();
  // A tile's grid holds the pyramid's level `extra` deeper (17-vertex blocks: 2 levels), so the
  // tree stops that much sooner.
  uint32_t extra = 0;
  while ((manifest.verticesPerSide - 1) << extra < kGridVertices - 1) ++extra;
  const auto sampleLevel = [&](uint32_t level) { return level + extra; };
  const uint32_t deepest = manifest.maxLevel() > extra ? manifest.maxLevel() - extra : 0;
  const uint32_t last = std::min(region.maxLevel, deepest);
  PyramidSurface surface(source, ellipsoid);
  ExportReport report;
  for (uint32_t level = region.minLevel; level <= last; ++level) {
    {
      for (const geo::TileId& tile : candidateTiles(manifest, level, region)) {
        auto summary = source.summary(tile);
        if (!summary) return Error{summary.error()};
        if (!*summary) continue;
        const std::filesystem::path path = outDir / std::to_string(level) / std::to_string(tile.x) /
                                           (std::to_string(tmsRow(tile)) + ".terrain");
        auto written = writeTileOnce(
            path,
            [&]() -> Result<std::vector<std::byte>> {
              auto heights = gridHeights(surface, tile, sampleLevel(tile.level));
              if (!heights) return Error{heights.error()};
              const BlockMesh mesh = quantizedMeshOfGrid(tile, kGridVertices, *heights, ellipsoid);
              return formats::gzipCompress(formats::encodeQuantizedMesh(mesh.mesh, mesh.culling),
                                           9);
            },
            report);
        if (!written) return Error{written.error()};
      }
    }
  }
  // What the tree holds, this run's tiles and earlier runs' (another region, other levels).
  std::vector<std::set<std::pair<uint32_t, uint32_t>>> present;  // per level: (TMS row, column)
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
  nlohmann::json available = nlohmann::json::array();
  for (const auto& level : present) available.push_back(availableRanges(level));
  const nlohmann::json layer = {
      {"tilejson", "2.1.0"},
      {"name", outDir.filename().string()},
      {"description", "Exported by globe-tiler from " + source.location()},
      {"version", treeVersion(manifest)},
      {"format", "quantized-mesh-1.0"},
      {"scheme", "tms"},
      {"tiles", {"{z}/{x}/{y}.terrain?v={version}"}},
      {"projection", "EPSG:4326"},
      {"bounds", {-180, -90, 180, 90}},
      {"minzoom", 0},
      {"maxzoom", present.empty() ? 0 : present.size() - 1},
      {"available", available},
      {"attribution", source.attribution()}};
  const std::string text = layer.dump(1);
  const std::vector<std::byte> bytes(reinterpret_cast<const std::byte*>(text.data()),
                                     reinterpret_cast<const std::byte*>(text.data()) + text.size());
  // layer.json last and always rewritten: it lists what this and earlier runs wrote.
  std::error_code error;
  std::filesystem::create_directories(outDir, error);
  std::filesystem::remove(outDir / "layer.json", error);
  ExportReport ignored;
  if (auto written = writeTileOnce(
          outDir / "layer.json", [&]() -> Result<std::vector<std::byte>> { return bytes; },
          ignored);
      !written) {
    return Error{written.error()};
  }
  return report;
}

}  // namespace globe::publish
