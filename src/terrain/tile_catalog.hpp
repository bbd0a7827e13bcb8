// What tile selection asks of the pyramid and the loader: which tiles exist (with the height
// bounds of their subtrees) and which are loaded. The app implements it over io::TileStore.
#pragma once

#include <limits>
#include <optional>

#include "geo/tile_id.hpp"
#include "terrain/height_block.hpp"

namespace globe::terrain {

struct TileSummary {
  // Bounds of the tile's vertices and of all its descendants' (metres, sea = 0 m).
  HeightRange subtreeHeightRange;
  // How far the tile's surface lies from the finer data under it, as the tiler measured it
  // (metres, formats/pack_format.hpp); NaN when the pyramid does not say (screen_space_error.hpp).
  double measuredGeometricErrorMeters = std::numeric_limits<double>::quiet_NaN();
};

class TileCatalog {
 public:
  virtual ~TileCatalog() = default;
  // nullopt: the pyramid has no such tile. A tile has either no children or all four.
  virtual std::optional<TileSummary> find(const geo::TileId& tile) const = 0;
  // The tile's block is loaded and drawable now.
  virtual bool isResident(const geo::TileId& tile) const = 0;
};

}  // namespace globe::terrain
