// What every terrain service source shares (quantized-mesh, heightmap-1.0, Terrarium,
// Terrain-RGB): the quadtree the service's tiles make, blocks assembled from the heights a
// subclass samples at the grid's vertices, and tiles the service lacks (not published, or 404)
// made from their parent's surface, so a missing tile draws its parent's ground, never an error.
// A service publishes no height bounds ahead of its tiles: a tile's summary is its own block's
// range once loaded, else its nearest loaded ancestor's, widened.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/vec3.hpp>

#include "geo/ellipsoid.hpp"
#include "services/recent_items.hpp"
#include "streaming/terrain_source.hpp"
#include "terrain/tin_tile.hpp"

namespace globe::services {

// Vertices per side of a service's blocks: the 65-sample grid Cesium's heightmaps and ctb's
// meshes are made on, and a 256-pixel Web-Mercator tile's pixels one level up.
inline constexpr uint32_t kServiceVerticesPerSide = 65;

// Heights a subclass sampled for one tile at the block's vertices and its apron: rows and
// columns -w..N+w-1 (w = terrain::kApronWidth), row-major from the north-west.
struct ServiceSamples {
  // NaN where the service has nothing (its tile there is missing): the parent's surface is taken.
  std::vector<double> heightMeters;
  std::vector<uint8_t> water;      // 1 where water (sea at 0 m over heightMeters), or empty
  std::vector<glm::vec3> normals;  // the block's N² vertices (ECEF, unit), or empty
  // The tile's own triangles when the service gives a TIN (quantized-mesh): the block draws
  // and collides with them (terrain/height_block.hpp).
  std::shared_ptr<const terrain::TinTile> tin;
  static size_t side() { return kServiceVerticesPerSide + 2 * terrain::kApronWidth; }
  static size_t count() { return side() * side(); }
};

// The manifest a service's source shows (info, native resolution).
struct ServiceDescription {
  std::string location;  // as the user gave it
  std::string format;    // "quantized-mesh-1.0", "heightmap-1.0", "terrarium", "terrain-rgb"
  uint32_t maxLevel = 0;
  double stepDegrees = 0;  // the finest sample step
  formats::BoundsDegrees bounds{-180, -90, 180, 90};
  std::string attribution;
  bool remote = false;
};

class ServiceTerrainSource : public streaming::TerrainSource {
 public:
  ServiceTerrainSource(const ServiceDescription& description, terrain::SeaSurface sea);

  const formats::PyramidManifest& manifest() const override { return manifest_; }
  const std::string& location() const override { return location_; }
  using TerrainSource::location;
  bool remote() const override { return remote_; }
  terrain::SeaSurface sea() const override { return sea_; }
  std::string attribution() const override { return attribution_; }

  Peek peek(const geo::TileId& tile, terrain::TileSummary* summary) override;
  Result<std::optional<terrain::TileSummary>> summary(const geo::TileId& tile) override;
  Result<std::optional<terrain::HeightBlock>> load(const geo::TileId& tile) override;
  Result<terrain::HeightBlock> loadBlock(const geo::TileId& tile) override;
  std::vector<std::string> takeNewSourceErrors() override;

  // Tiles fetched from the service, and made from a parent instead.
  uint64_t tilesFetched() const { return fetched_.load(); }
  uint64_t tilesFromParent() const { return fromParent_.load(); }

 protected:
  // Whether the service publishes this tile itself (its availability).
  virtual bool publishes(const geo::TileId& tile) const = 0;
  // The tile's samples; nullopt when the server has no such tile after all (404).
  virtual Result<std::optional<ServiceSamples>> fetchSamples(const geo::TileId& tile) = 0;
  // A problem with the whole service, reported once (takeNewSourceErrors).
  void noteServiceError(const std::string& message);

 private:
  bool exists(const geo::TileId& tile) const;
  terrain::HeightBlock assemble(const ServiceSamples& samples) const;
  // Samples the service has nothing for (NaN) take the parent's surface.
  Result<void> fillFromParent(const geo::TileId& tile, ServiceSamples& samples);
  std::optional<terrain::HeightRange> knownRange(const geo::TileId& tile) const;
  void remember(const geo::TileId& tile, const terrain::HeightBlock& block);

  formats::PyramidManifest manifest_;
  std::string location_;
  std::string attribution_;
  bool remote_;
  terrain::SeaSurface sea_;
  geo::Ellipsoid ellipsoid_;
  std::atomic<uint64_t> fetched_{0}, fromParent_{0};

  mutable std::mutex mutex_;
  std::unordered_map<geo::TileId, terrain::HeightRange> ranges_;  // of loaded blocks
  // Recent blocks, for children made from them without fetching them again.
  RecentItems<geo::TileId, std::shared_ptr<const terrain::HeightBlock>> recent_{32};
  std::vector<std::string> newErrors_;
  std::vector<std::string> reportedErrors_;
};

}  // namespace globe::services
