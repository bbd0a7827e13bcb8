// One tile the viewer wants loaded, and how urgently (higher priority = sooner).
#pragma once

#include "geo/tile_id.hpp"

namespace globe::streaming {

struct LoadRequest {
  geo::TileId tile;
  double priority = 0;  // higher loads sooner; NaN counts as the lowest
};

}  // namespace globe::streaming
