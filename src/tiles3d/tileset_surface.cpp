#include "tiles3d/tileset_surface.hpp"

#include <algorithm>

namespace globe::tiles3d {
namespace {

void keepHigher(std::optional<double>& best, const std::optional<double>& h) {
  if (h && (!best || *h > *best)) best = h;
}

}  // namespace

Result<TilesetSurface> TilesetSurface::load(const Tileset& tileset,
                                            const geo::Ellipsoid& ellipsoid) {
  TilesetSurface surface;
  surface.warnings_ = tileset.warnings;
  surface.root_ = surface.build(tileset, tileset.root, ellipsoid);
  std::vector<const HeightGrid*> drawn;
  for (const auto& content : surface.drawnContents()) drawn.push_back(&content->grid);
  surface.merged_ = HeightGrid::merge(drawn, kMaxMergedGridCells);
  return surface;
}

TilesetSurface::Node TilesetSurface::build(const Tileset& tileset, const TileNode& tile,
                                           const geo::Ellipsoid& ellipsoid) {
  Node node;
  node.additive = tile.additive;
  for (const std::string& name : tile.contents) {
    auto content = loadTileContent(tileset, tile, name, ellipsoid);
    if (!content) {
      warnings_.push_back(content.error() + " (its parent's content stands in)");
      node.complete = false;
      continue;
    }
    ++contentsRead_;
    trianglesRead_ += content->triangleCount;
    if (!content->grid.empty()) {
      maximumMeters_ = std::max(maximumMeters_, content->grid.maximumHeightMeters());
    }
    node.contents.push_back(std::make_shared<const LoadedContent>(std::move(*content)));
  }
  for (const TileNode& child : tile.children)
    node.children.push_back(build(tileset, child, ellipsoid));
  return node;
}

std::optional<double> TilesetSurface::heightAt(double lon, double lat) const {
  return merged_.empty() ? heightAt(root_, lon, lat) : merged_.heightAt(lon, lat);
}

// REPLACE refines where every child's content could be read (a viewer keeps drawing the parent
// until its children are in); ADD always adds its children.
bool TilesetSurface::refines(const Node& node) {
  return !node.children.empty() &&
         (node.additive || std::all_of(node.children.begin(), node.children.end(),
                                       [](const Node& c) { return c.complete; }));
}

std::vector<std::shared_ptr<const LoadedContent>> TilesetSurface::drawnContents() const {
  std::vector<std::shared_ptr<const LoadedContent>> out;
  collectDrawn(root_, out);
  return out;
}

void TilesetSurface::collectDrawn(const Node& node,
                                  std::vector<std::shared_ptr<const LoadedContent>>& out) {
  if (!refines(node) || node.additive)
    out.insert(out.end(), node.contents.begin(), node.contents.end());
  if (!refines(node)) return;
  for (const Node& child : node.children) collectDrawn(child, out);
}

std::optional<double> TilesetSurface::heightAt(const Node& node, double lon, double lat) {
  std::optional<double> own;
  for (const auto& content : node.contents) keepHigher(own, content->grid.heightAt(lon, lat));
  if (!refines(node)) return own;
  std::optional<double> best = node.additive ? own : std::nullopt;
  for (const Node& child : node.children) keepHigher(best, heightAt(child, lon, lat));
  return best;
}

}  // namespace globe::tiles3d
