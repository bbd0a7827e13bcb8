// Surfaces drawn over the terrain that collision takes as ground too (3D Tiles' roofs and
// models): the highest at a point in O(1), never below what is drawn there. The rendering tile
// array carries one (rendering_tile_array.hpp); collision's probes take the higher of it and the
// terrain (collision/surface_probe.hpp).
#pragma once

#include <optional>

namespace globe::terrain {

class SurfaceOverlay {
 public:
  virtual ~SurfaceOverlay() = default;
  // The highest drawn surface at a point (radians, longitude canonical), nullopt where none.
  virtual std::optional<double> heightAt(double longitudeRadians, double latitudeRadians) const = 0;
  // The highest anywhere, or -inf for none.
  virtual double maximumHeightMeters() const = 0;
};

}  // namespace globe::terrain
