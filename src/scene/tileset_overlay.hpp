// The tilesets a scene shows (--tileset) as the surface overlay collision reads with the terrain
// (terrain/surface_overlay.hpp): the highest of their drawn surfaces at a point, as one frame
// drew them (each tileset's snapshot, tiles3d/drawn_surface.hpp).
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "terrain/surface_overlay.hpp"
#include "tiles3d/drawn_surface.hpp"

namespace globe::scene {

class TilesetOverlay final : public terrain::SurfaceOverlay {
 public:
  explicit TilesetOverlay(std::vector<std::shared_ptr<const tiles3d::DrawnSurface>> tilesets)
      : tilesets_(std::move(tilesets)) {}
  std::optional<double> heightAt(double longitudeRadians, double latitudeRadians) const override;
  double maximumHeightMeters() const override;

 private:
  std::vector<std::shared_ptr<const tiles3d::DrawnSurface>> tilesets_;
};

}  // namespace globe::scene
