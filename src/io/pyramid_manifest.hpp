// manifest.json of a tile pyramid: tiling scheme, block size, levels, bounds, sources, globe model.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "geo/ellipsoid.hpp"
#include "geo/result.hpp"
#include "io/pack_format.hpp"

namespace globe::io {

inline constexpr const char* kManifestFileName = "manifest.json";

struct BoundsDegrees {
  double west = 0, south = 0, east = 0, north = 0;
  auto operator<=>(const BoundsDegrees&) const = default;
};

struct LevelInfo {
  uint32_t level = 0;
  uint64_t tileCount = 0;
  BoundsDegrees bounds;              // union of the level's tile rectangles
  terrain::HeightRange heightRange;  // of the level's vertices, sea = 0 m
  std::vector<PackId> packs;         // the pack files of this level, sorted
};

struct SourceInfo {
  std::string path;
  std::string format;
  int64_t columns = 0, rows = 0;
  double stepDegrees = 0;  // the finer of the column and row steps
  BoundsDegrees bounds;    // the cells' extent
  uint32_t finestLevel = 0;
};

struct PyramidManifest {
  uint32_t verticesPerSide = 17;
  uint32_t packTilesPerSide = 64;
  geo::GlobeModel globeModel = geo::GlobeModel::Wgs84;
  std::vector<LevelInfo> levels;  // levels[i].level == i, from 0 to the finest level
  std::vector<SourceInfo> sources;

  uint32_t maxLevel() const { return levels.empty() ? 0 : levels.back().level; }
  uint64_t tileCount() const;
  PackLayout packLayout() const { return {packTilesPerSide, verticesPerSide}; }
};

std::string manifestToJson(const PyramidManifest& manifest);
Result<PyramidManifest> manifestFromJson(std::string_view text, const std::filesystem::path& path);
Result<PyramidManifest> readManifest(const std::filesystem::path& pyramidDir);

}  // namespace globe::io
