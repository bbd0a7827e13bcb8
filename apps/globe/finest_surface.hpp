// The exact surface of the finest pyramid tile under a point, read from the tile store: for
// `globe play`'s log where no drawn tile lies under the camera (its nadir outside the view).
#pragma once

#include <optional>

#include "core/result.hpp"
#include "geo/ellipsoid.hpp"
#include "geo/tile_id.hpp"
#include "streaming/terrain_source.hpp"
#include "terrain/height_block.hpp"

namespace globe::app {

class FinestSurface {
 public:
  FinestSurface(streaming::TerrainSource& store, const geo::Ellipsoid& ellipsoid)
      : store_(store), ellipsoid_(ellipsoid) {}

  // Height above the ellipsoid of the finest tile's mesh along the normal (collision's exact
  // surface); 0 m where the pyramid has no tile. Errors: unreadable packs.
  Result<double> heightMeters(double longitudeRadians, double latitudeRadians);

 private:
  streaming::TerrainSource& store_;
  geo::Ellipsoid ellipsoid_;
  std::optional<geo::TileId> tile_;  // the last block read, kept for the next frames
  terrain::HeightBlock block_;
};

}  // namespace globe::app
