// Terrain shadows for the drawn tiles (collision/sun_visibility.hpp), kept per tile for the Sun's
// direction they were computed for: recomputed when the Sun moves by more than ~0.05° or the tile
// is uploaded again, and only once the view's tiles have all arrived (the array they march over
// is then the view's final one). Deterministic: the same tiles in the same order each run.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <unordered_map>

#include <glm/vec3.hpp>

#include "geo/ellipsoid.hpp"
#include "geo/tile_id.hpp"
#include "scene/tile_gpu.hpp"
#include "terrain/rendering_tile_array.hpp"

namespace globe::scene {

class TileSunlight {
 public:
  // Gives the drawn tiles of `array` whose shadows are stale theirs, at most `tilesPerFrame` (0:
  // all); returns how many stay stale. `settled`: the view's loads are done (else nothing is
  // computed and every stale tile counts).
  size_t update(const terrain::RenderingTileArray& array, const geo::Ellipsoid& ellipsoid,
                const glm::dvec3& sunDirectionEcef, TileGpu& gpu, uint32_t tilesPerFrame,
                bool settled);
  // The tile's mesh was uploaded again or left the GPU (its shadows went with it).
  void forget(const geo::TileId& tile) { sunKeys_.erase(tile); }

 private:
  using SunKey = std::array<int32_t, 3>;
  std::unordered_map<geo::TileId, SunKey> sunKeys_;
};

}  // namespace globe::scene
