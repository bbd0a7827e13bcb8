// A tileset's highest drawn surface anywhere, at its finest levels, as `globe query --tileset`
// answers and collision reads: every content read into a height grid (height_grid.hpp), then at
// a point, by the refinement the tileset says: REPLACE, the children's surface where every
// child's content could be read (else the parent's, as a viewer keeps drawing it); ADD, the
// higher of the tile's own and its children's. A content that cannot be read is named in the
// warnings and its coarser ancestor stands in.
#pragma once

#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/result.hpp"
#include "geo/ellipsoid.hpp"
#include "tiles3d/height_grid.hpp"
#include "tiles3d/loaded_content.hpp"
#include "tiles3d/tileset.hpp"

namespace globe::tiles3d {

inline constexpr uint32_t kMaxMergedGridCells = 2048;  // a side of a tileset's merged grid

class TilesetSurface {
 public:
  static Result<TilesetSurface> load(const Tileset& tileset, const geo::Ellipsoid& ellipsoid);

  // The highest drawn surface at a point (radians), nullopt where the tileset has none.
  std::optional<double> heightAt(double longitudeRadians, double latitudeRadians) const;

  // The contents drawn at the finest levels, by the same refinement rule as heightAt.
  std::vector<std::shared_ptr<const LoadedContent>> drawnContents() const;
  // The highest surface anywhere in the tileset (metres), or -inf when it has none.
  double maximumHeightMeters() const { return maximumMeters_; }

  const std::vector<std::string>& warnings() const { return warnings_; }
  size_t contentsRead() const { return contentsRead_; }
  size_t trianglesRead() const { return trianglesRead_; }

 private:
  struct Node {
    bool additive = false;
    bool complete = true;  // every content read
    std::vector<std::shared_ptr<const LoadedContent>> contents;
    std::vector<Node> children;
  };
  Node build(const Tileset& tileset, const TileNode& tile, const geo::Ellipsoid& ellipsoid);
  static std::optional<double> heightAt(const Node& node, double lon, double lat);
  static void collectDrawn(const Node& node,
                           std::vector<std::shared_ptr<const LoadedContent>>& out);
  static bool refines(const Node& node);

  Node root_;
  // The drawn contents' grids as one (heightAt reads one cell); empty: read the tree.
  HeightGrid merged_;
  std::vector<std::string> warnings_;
  size_t contentsRead_ = 0, trianglesRead_ = 0;
  double maximumMeters_ = -std::numeric_limits<double>::infinity();
};

}  // namespace globe::tiles3d
