#include "tiles3d/tileset_selection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace globe::tiles3d {
namespace {

void flatten(const TileNode& node, uint32_t parent, std::vector<FlatTile>& out) {
  const auto index = static_cast<uint32_t>(out.size());
  out.push_back({&node, parent, {}});
  if (parent != UINT32_MAX) out[parent].children.push_back(index);
  for (const TileNode& child : node.children) flatten(child, index, out);
}

struct Traversal {
  std::span<const FlatTile> tiles;
  std::span<const ContentState> states;
  const TileSelectionView& view;
  TileChoice choice;

  bool inView(const BoundingSphere& s) const {
    if (!std::isfinite(s.radiusMeters)) return true;
    if (s.distanceMeters(view.cameraEcefMeters) <= view.nearbyMeters) return true;
    for (int p = 0; p < 5; ++p) {  // the far plane is left out
      const geo::Plane& plane = view.frustum.planes[static_cast<size_t>(p)];
      if (glm::dot(plane.normal, s.centerEcefMeters) + plane.distance < -s.radiusMeters)
        return false;
    }
    return true;
  }
  double screenErrorPixels(const TileNode& node) const {
    const double distance = node.bounds.distanceMeters(view.cameraEcefMeters);
    if (distance <= 0) return std::numeric_limits<double>::infinity();
    return node.geometricErrorMeters * view.pixelsPerRadian / distance;
  }
  // Draws the tile's content, or asks for it.
  void draw(uint32_t t, double priority) {
    if (states[t] == ContentState::Ready) {
      if (!tiles[t].node->contents.empty()) choice.drawn.push_back(t);
    } else if (states[t] == ContentState::Missing) {
      choice.wanted.push_back({t, priority});
    }
  }
  void visit(uint32_t t);
};

void Traversal::visit(uint32_t t) {
  ++choice.visited;
  const FlatTile& tile = tiles[t];
  if (!inView(tile.node->bounds)) {
    ++choice.culled;
    return;
  }
  const double error = screenErrorPixels(*tile.node);
  const double priority = std::min(error, 1e12);
  if (tile.children.empty() || error <= view.maximumScreenSpaceErrorPixels) {
    draw(t, priority);
    return;
  }
  if (tile.node->additive) {
    draw(t, priority);
    for (const uint32_t c : tile.children) visit(c);
    return;
  }
  // REPLACE: the children in view must all be drawable before they stand in for this tile.
  bool ready = true, failed = false;
  for (const uint32_t c : tile.children) {
    if (!inView(tiles[c].node->bounds)) continue;
    failed = failed || states[c] == ContentState::Failed;
    if (states[c] == ContentState::Missing) {
      ready = false;
      choice.wanted.push_back({c, priority});
    }
  }
  if (ready && !failed) {
    for (const uint32_t c : tile.children) visit(c);
    return;
  }
  draw(t, priority);
}

}  // namespace

std::vector<FlatTile> flattenTileset(const Tileset& tileset) {
  std::vector<FlatTile> out;
  out.reserve(tileset.tileCount);
  flatten(tileset.root, UINT32_MAX, out);
  return out;
}

TileChoice selectTiles(std::span<const FlatTile> tiles, std::span<const ContentState> states,
                       const TileSelectionView& view) {
  Traversal traversal{tiles, states, view, {}};
  if (!tiles.empty() && states.size() == tiles.size()) traversal.visit(0);
  return std::move(traversal.choice);
}

}  // namespace globe::tiles3d
