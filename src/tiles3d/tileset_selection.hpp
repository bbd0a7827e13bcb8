// Which tiles of a tileset a view draws and which contents it wants loaded: the 3D Tiles
// traversal by screen-space error (CesiumJS's and cesium-native's rule, as the terrain's):
// a tile refines while its geometric error seen from the camera spans more than the
// maximum pixels. REPLACE draws its children only once every child in view can be drawn
// (loaded, or without content), the parent meanwhile; a child whose content failed keeps its
// parent drawn there for good (carry on with the coarser level). ADD draws a tile and its
// refining children together. Tiles out of the frustum are skipped, except those within
// `nearbyMeters` of the camera: collision looks around, not only ahead. Pure: no loads, no GL.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "geo/frustum.hpp"
#include "tiles3d/tileset.hpp"

namespace globe::tiles3d {

// The tileset's tree in one array, parents before their children.
struct FlatTile {
  const TileNode* node = nullptr;
  uint32_t parent = UINT32_MAX;
  std::vector<uint32_t> children;
};
std::vector<FlatTile> flattenTileset(const Tileset& tileset);

enum class ContentState : uint8_t {
  Missing,  // not loaded (or loading)
  Ready,    // loaded, or a tile without content
  Failed,   // its content could not be read: never drawn
};

struct TileSelectionView {
  glm::dvec3 cameraEcefMeters{0.0};
  geo::Frustum frustum;  // its far plane is not used (the terrain's depth has no far plane)
  // Pixels a radian spans on screen: heightPixels / (2 tan(fovY / 2)).
  double pixelsPerRadian = 1000;
  double maximumScreenSpaceErrorPixels = 16;  // CesiumJS's default for 3D Tiles
  double nearbyMeters = 200;
};

struct TileWish {
  uint32_t tile;
  double priority;  // higher loads sooner
};

struct TileChoice {
  std::vector<uint32_t> drawn;   // tiles whose contents are drawn (all Ready)
  std::vector<TileWish> wanted;  // tiles whose contents this view needs and lacks
  uint32_t visited = 0, culled = 0;
  bool complete() const { return wanted.empty(); }
};

TileChoice selectTiles(std::span<const FlatTile> tiles, std::span<const ContentState> states,
                       const TileSelectionView& view);

}  // namespace globe::tiles3d
