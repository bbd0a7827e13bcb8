// manifest.json of a tile pyramid: tiling scheme, block size, levels, bounds, sources, globe model.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/result.hpp"
#include "formats/pack_format.hpp"
#include "formats/vertical_units.hpp"
#include "geo/ellipsoid.hpp"
#include "transport/byte_source.hpp"

namespace globe::formats {

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
  // Per pack, its stored index's bytes (version-5 packs), so that a reader asks for exactly the
  // header and index in one read; empty when the manifest does not say (older pyramids).
  std::vector<uint32_t> packIndexBytes{};
};

// What the tiler did to a source's samples before tiling (docs/conditioning.md).
struct SourceConditioning {
  uint64_t noDataSamples = 0;        // in the source as given
  uint64_t seaSamples = 0;           // written as water
  uint64_t voidSamples = 0;          // no data inside land
  uint64_t interpolatedSamples = 0;  // voids filled from their border
  uint64_t fromCoarserSamples = 0;   // voids filled from a coarser source (delta surface)
  uint64_t unfilledSamples = 0;      // voids left as no data (nothing to fill them from)
  uint64_t outsideSamples = 0;       // no data outside its footprint: the coarser surface, bent
  double bendMarginDegrees = 0;      // over which coarser sources bend to meet its edges
  bool noDataIsWater = false;        // its no data is its water code (GTOPO30's ocean mask)
  bool operator==(const SourceConditioning&) const = default;
};

struct SourceInfo {
  std::string path;
  std::string format;
  int64_t columns = 0, rows = 0;
  double stepDegrees = 0;  // the finer of the column and row steps
  BoundsDegrees bounds;    // the cells' extent
  uint32_t finestLevel = 0;
  SourceConditioning conditioning;
  // How its stored values became metres; unset in manifests written before it was recorded.
  std::optional<VerticalUnits> verticalUnits{};
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

// The finest source whose cells cover a point (the smallest step; longitudes taken modulo 360),
// null where none does: what the terrain drawn there was made from (the HUD says it).
const SourceInfo* finestSourceAt(const PyramidManifest& manifest, double longitudeDegrees,
                                 double latitudeDegrees);

std::string manifestToJson(const PyramidManifest& manifest);
Result<PyramidManifest> manifestFromJson(std::string_view text, const std::filesystem::path& path);
Result<PyramidManifest> readManifest(const std::filesystem::path& pyramidDir);
// The manifest of a pyramid in a directory or on a server.
Result<PyramidManifest> readManifest(transport::ByteSource& source);
// Manifests larger than this are refused (a server cannot make the viewer allocate more).
inline constexpr size_t kMaxManifestFileBytes = size_t{1} << 28;

}  // namespace globe::formats
