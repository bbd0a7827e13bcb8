// globe-bench's terrain: the bundled pyramid, rendering tile arrays of n real 17x17 blocks
// around Mount Fuji, a camera flight path near the surface and random camera positions.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <random>
#include <unordered_map>
#include <vector>

#include <glm/vec3.hpp>

#include "core/result.hpp"
#include "geo/ellipsoid.hpp"
#include "geo/globe_rectangle.hpp"
#include "geo/tile_id.hpp"
#include "streaming/tile_store.hpp"
#include "terrain/height_block.hpp"
#include "terrain/rendering_tile_array.hpp"

namespace globe::bench {

// The pyramid the benchmarks read: an existing directory, or the bundled data/dem tiled into a
// temporary directory (removed with the object).
class Pyramid {
 public:
  static Result<std::unique_ptr<Pyramid>> open(const std::filesystem::path& directory);
  ~Pyramid();
  Pyramid(const Pyramid&) = delete;
  Pyramid& operator=(const Pyramid&) = delete;

  const formats::PyramidManifest& manifest() const { return store_->manifest(); }
  geo::Ellipsoid ellipsoid() const { return geo::ellipsoidFor(manifest().globeModel); }
  bool has(const geo::TileId& tile);
  // The tile's block, loaded once; an empty block when it cannot be read.
  const terrain::HeightBlock& block(const geo::TileId& tile);
  // Every existing tile of the level whose rectangle intersects the rectangle (degrees).
  std::vector<geo::TileId> tilesOfLevel(uint32_t level, double westDegrees, double southDegrees,
                                        double eastDegrees, double northDegrees);

 private:
  Pyramid(std::unique_ptr<streaming::TileStore> store, std::filesystem::path scratch)
      : store_(std::move(store)), scratch_(std::move(scratch)) {}
  std::unique_ptr<streaming::TileStore> store_;
  std::filesystem::path scratch_;
  std::unordered_map<geo::TileId, terrain::HeightBlock> blocks_;
};

// Mount Fuji's summit, the centre of every benchmark array.
inline constexpr double kFujiSummitLongitudeDegrees = 138.7274;
inline constexpr double kFujiSummitLatitudeDegrees = 35.3606;
// The deepest level of the bundled Fuji data (3" SRTM): 94 x 94 tiles of ~1 km.
inline constexpr uint32_t kBenchLevel = 14;

// A rendering tile array of `tiles` level-14 tiles: a width x height rectangle of the scheme's
// tiles around the summit tile (10 = 5x2, 100 = 10x10, 1000 = 40x25, 10000 = 100x100,
// 100000 = 400x250; other counts: the most nearly square exact factorisation). Each tile holds
// its own copy of a real block: the pyramid's block of that very tile inside the Fuji data
// (all tiles up to 1000; 8836 of 10000), beyond it the Fuji block at the same position modulo
// the 94 x 94 Fuji tiles (a periodic tiling of real heights).
struct BenchArray {
  uint32_t width = 0, height = 0;
  geo::GlobeRectangle bounds{};    // of the rectangle
  uint32_t realPositionTiles = 0;  // tiles whose block is the pyramid's block of that tile
  std::vector<terrain::HeightBlock> blocks;
  terrain::RenderingTileArray array;
};
Result<std::unique_ptr<BenchArray>> makeBenchArray(Pyramid& pyramid, uint32_t tiles);

// The flight area: the 10-tile (5x2) rectangle, contained in every larger array.
geo::GlobeRectangle flightArea();

struct CameraQuery {
  glm::dvec3 ecefMeters{0.0};
  double longitudeRadians = 0, latitudeRadians = 0;
  double heightMeters = 0;        // D, above the ellipsoid
  double aboveSurfaceMeters = 0;  // D minus the exact drawn surface
};

// One frame per query at 60 Hz: a camera flying at 50 m/s with a randomly wandering heading
// (bouncing off the flight area's edges, 50 m inside them) at 20..300 m above the drawn surface
// (a sinusoid of ~10 s with a wandering phase). The same path for every array size.
std::vector<CameraQuery> flightPath(const terrain::RenderingTileArray& flightAreaArray,
                                    const geo::GlobeRectangle& area,
                                    const geo::Ellipsoid& ellipsoid, size_t frames, uint64_t seed);

// Independent positions, uniform in longitude and latitude over the rectangle, 20..300 m above
// the drawn surface of the array.
std::vector<CameraQuery> randomQueries(const terrain::RenderingTileArray& array,
                                       const geo::GlobeRectangle& rectangle,
                                       const geo::Ellipsoid& ellipsoid, size_t count,
                                       uint64_t seed);

}  // namespace globe::bench
