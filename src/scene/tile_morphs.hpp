// Finer tiles rising out of the coarser surface they replace, near the camera. A tile that
// arrives late (a remote pyramid, a fast descent) would otherwise change the ground under the
// camera in one frame, and collision would pop the camera up by the difference; morphing the
// tile from the surface drawn there before to its own over `frames` frames lifts the camera with
// the ground, a fraction of the difference per frame, while drawing and collision still read one
// and the same surface (docs/collision.md, "Loading").
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "geo/ellipsoid.hpp"
#include "geo/tile_id.hpp"
#include "terrain/height_block.hpp"

namespace globe::scene {

class TileMorphs {
 public:
  // frames <= 1: no morphs (every block is drawn as it is).
  TileMorphs(uint32_t frames, const geo::Ellipsoid& ellipsoid)
      : frames_(frames), ellipsoid_(ellipsoid) {}

  struct Choice {
    std::shared_ptr<const terrain::HeightBlock> block;  // to draw and collide with this frame
    bool upload = false;  // the GPU's mesh for the tile must be replaced by this block's
  };
  // The block for `tile` this frame: `loaded`, or (for a tile near the camera that was not in
  // last frame's array where a coarser ancestor was) a morph from the ancestor's surface as it
  // was drawn, advanced one frame per call until it is `loaded`. Call once per tile of the
  // frame's collision array: drawn (its mesh follows the morph) or only collided with.
  Choice blockFor(const geo::TileId& tile, std::shared_ptr<const terrain::HeightBlock> loaded,
                  bool nearCamera, bool drawn = true);
  // Ends the frame: returns the tiles whose GPU mesh is a morph's that will not be finished (not
  // drawn, their morph dropped): release them. A morph whose tile leaves the array is kept
  // `frames` frames, so a tile that flickers out and back goes on from where it was.
  std::vector<geo::TileId> endFrame();
  size_t active() const { return morphs_.size(); }

  // Whether a tile's rectangle comes within radiusMeters of the point (spherical approximation
  // of the ground distance, mean Earth radius: the morph region need not be exact).
  static bool isNear(const geo::TileId& tile, double longitudeRadians, double latitudeRadians,
                     double radiusMeters);

 private:
  struct Morph {
    std::shared_ptr<const terrain::HeightBlock> from;  // the surface drawn there before
    uint32_t step = 0;                                 // frames of the morph shown so far
    uint64_t lastFrame = 0;                            // the frame it was last shown
  };
  // The surface in last frame's array over `tile` by its nearest ancestor there, at tile's level.
  std::shared_ptr<const terrain::HeightBlock> previousSurface(const geo::TileId& tile) const;
  Choice advance(const geo::TileId& tile, Morph& morph,
                 const std::shared_ptr<const terrain::HeightBlock>& loaded, bool drawn);

  uint32_t frames_;
  geo::Ellipsoid ellipsoid_;
  uint64_t frame_ = 0;
  std::unordered_map<geo::TileId, Morph> morphs_;
  // Tiles whose GPU mesh was last uploaded from a morph block.
  std::unordered_set<geo::TileId> morphMeshes_;
  // The blocks of last frame's array and this frame's, by tile; the tiles drawn this frame.
  std::unordered_map<geo::TileId, std::shared_ptr<const terrain::HeightBlock>> previous_, current_;
  std::unordered_set<geo::TileId> drawnNow_;
};

}  // namespace globe::scene
