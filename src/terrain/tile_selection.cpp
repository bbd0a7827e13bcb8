// The quadtree traversal behind selectTiles: culling, screen-space error with hysteresis, and
// the residency rule that never leaves a hole.
#include "terrain/tile_selection.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <unordered_set>

#include "geo/bounding_region.hpp"
#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "terrain/screen_space_error.hpp"

namespace globe::terrain {

namespace {

geo::RegionVolume volumeOf(const geo::TileId& tile, const TileSummary& summary,
                           const geo::Ellipsoid& ellipsoid) {
  const geo::BoundingRegion region{geo::GeographicTilingScheme::tileRectangle(tile),
                                   static_cast<double>(summary.subtreeHeightRange.minimumMeters),
                                   static_cast<double>(summary.subtreeHeightRange.maximumMeters)};
  return geo::RegionVolume::fromRegion(region, ellipsoid);
}

// Every strict ancestor of a previous tile was refined last frame.
std::unordered_set<geo::TileId> refinedLastFrame(const std::vector<geo::TileId>& previousTiles) {
  std::unordered_set<geo::TileId> refined;
  for (const geo::TileId& tile : previousTiles) {
    if (!geo::GeographicTilingScheme::isValid(tile)) continue;
    for (geo::TileId t = tile; t.level > 0;) {
      t = t.parent();
      if (!refined.insert(t).second) break;  // its ancestors are in already
    }
  }
  return refined;
}

// A visited tile that passed culling.
struct VisibleTile {
  geo::TileId tile;
  double distanceMeters;
  TileSummary summary;
  double faceOn;  // screen_space_error.hpp: faceOnFraction of its volume
  bool measured;  // refines by the tiler's measured error (else the level's nominal one)
};

class Traversal {
 public:
  Traversal(const SelectionView& view, const TileCatalog& catalog, const SelectionOptions& options,
            const std::vector<geo::TileId>& previousTiles)
      : view_(view),
        catalog_(catalog),
        options_(options),
        refined_(refinedLastFrame(previousTiles)) {
    const auto camera = geo::ecefToCartographic(view.ellipsoid, view.cameraEcefMeters);
    cameraHeightMeters_ = camera ? camera->heightMeters : std::numeric_limits<double>::quiet_NaN();
    const double threshold = options.maximumScreenSpaceErrorPixels;
    threshold_ = threshold > 0.0 ? threshold : 2.0;  // +inf: never refine
    const double h = options.hysteresisFraction;
    hysteresis_ = h > 0.0 ? std::min(h, 0.9) : 0.0;
  }

  SelectionResult run() {
    for (const geo::TileId root : {geo::TileId{0, 0, 0}, geo::TileId{0, 1, 0}}) {
      const std::optional<TileSummary> summary = catalog_.find(root);
      if (!summary) continue;
      const std::optional<VisibleTile> visible = cull(root, *summary);
      if (!visible) continue;
      if (!catalog_.isResident(root)) {
        request(root, std::numeric_limits<double>::max());
        continue;
      }
      descend(*visible);
    }
    std::sort(result_.requests.begin(), result_.requests.end(),
              [](const TileRequest& a, const TileRequest& b) {
                if (a.priority != b.priority) return a.priority > b.priority;
                return a.tile < b.tile;  // level first: coarser sooner
              });
    result_.counters.selected = result_.tiles.size();
    return std::move(result_);
  }

 private:
  // Counts the visit (unless `count` is false: a lookahead); nullopt when the tile is culled.
  std::optional<VisibleTile> cull(const geo::TileId& tile, const TileSummary& summary,
                                  bool count = true) {
    if (count) ++result_.counters.visited;
    const geo::RegionVolume volume = volumeOf(tile, summary, view_.ellipsoid);
    if (geo::cullRegion(view_.frustum, volume) == geo::CullResult::Outside) {
      if (count) ++result_.counters.culledByFrustum;
      return std::nullopt;
    }
    if (geo::isBelowHorizon(view_.cameraEcefMeters, volume)) {
      if (count) ++result_.counters.culledByHorizon;
      return std::nullopt;
    }
    const bool measured = options_.measuredErrors && !inNominalErrorRegion(tile);
    const double faceOn =
        measured ? faceOnFraction(view_.cameraEcefMeters, volume.pointsEcefMeters, view_.ellipsoid)
                 : 1.0;
    return VisibleTile{
        tile, distanceLowerBoundMeters(view_.cameraEcefMeters, cameraHeightMeters_, volume),
        summary, faceOn, measured};
  }

  bool inNominalErrorRegion(const geo::TileId& tile) const {
    if (options_.nominalErrorRegions.empty()) return false;
    const geo::GlobeRectangle rectangle = geo::GeographicTilingScheme::tileRectangle(tile);
    return std::any_of(options_.nominalErrorRegions.begin(), options_.nominalErrorRegions.end(),
                       [&](const NominalErrorRegion& region) {
                         return tile.level <= region.throughLevel &&
                                region.rectangle.intersects(rectangle);
                       });
  }

  void request(const geo::TileId& tile, double priority) {
    ++result_.counters.wantedNotResident;
    result_.requests.push_back({tile, priority});
  }

  // The descendants of a tile waiting to be drawn that the refinement will want once it is:
  // requested now, at lower priority, `levels` deep (SelectionOptions::lookaheadLevels).
  void lookahead(const VisibleTile& visible, uint32_t levels, double priority) {
    const geo::TileId& tile = visible.tile;
    if (levels == 0 || tile.level >= options_.maximumLevel || tile.level >= geo::kMaxLevel) return;
    const double factor = refined_.contains(tile) ? 1.0 - hysteresis_ : 1.0 + hysteresis_;
    if (!(errorPixels(visible, visible.distanceMeters) > factor * threshold_)) return;
    const std::array<geo::TileId, 4> children = tile.children();
    std::array<std::optional<TileSummary>, 4> summaries;
    for (size_t i = 0; i < 4; ++i) {
      summaries[i] = catalog_.find(children[i]);
      if (!summaries[i]) return;
    }
    for (size_t i = 0; i < 4; ++i) {
      const std::optional<VisibleTile> child = cull(children[i], *summaries[i], false);
      if (!child) continue;
      if (!catalog_.isResident(children[i])) {
        result_.requests.push_back({children[i], priority, true});
      }
      lookahead(*child, levels - 1, priority / 4);
    }
  }

  double errorPixels(const VisibleTile& visible, double distanceMeters) const {
    const double measured = visible.measured ? visible.summary.measuredGeometricErrorMeters
                                             : std::numeric_limits<double>::quiet_NaN();
    return screenSpaceErrorPixels(
        tileGeometricErrorMeters(visible.tile.level, options_.verticesPerSide, view_.ellipsoid,
                                 measured, visible.faceOn),
        distanceMeters, view_);
  }

  // A visible, resident tile: draws itself or is refined into its visible children.
  void descend(const VisibleTile& visible) {
    const geo::TileId& tile = visible.tile;
    const double error = errorPixels(visible, visible.distanceMeters);
    const double factor = refined_.contains(tile) ? 1.0 - hysteresis_ : 1.0 + hysteresis_;
    if (!(error > factor * threshold_) || tile.level >= options_.maximumLevel ||
        tile.level >= geo::kMaxLevel) {
      result_.tiles.push_back(tile);
      return;
    }
    const std::array<geo::TileId, 4> children = tile.children();
    std::array<std::optional<TileSummary>, 4> summaries;
    for (size_t i = 0; i < 4; ++i) {
      summaries[i] = catalog_.find(children[i]);
      if (!summaries[i]) {  // a leaf of the pyramid (families are whole)
        result_.tiles.push_back(tile);
        return;
      }
    }
    std::array<std::optional<VisibleTile>, 4> visibleChildren;
    std::array<bool, 4> resident{};
    bool allResident = true;
    for (size_t i = 0; i < 4; ++i) {
      visibleChildren[i] = cull(children[i], *summaries[i]);
      if (!visibleChildren[i]) continue;
      resident[i] = catalog_.isResident(children[i]);
      allResident = allResident && resident[i];
    }
    if (allResident) {
      ++result_.counters.refined;
      for (const std::optional<VisibleTile>& child : visibleChildren) {
        if (child) descend(*child);
      }
      return;
    }
    result_.tiles.push_back(tile);
    for (size_t i = 0; i < 4; ++i) {
      if (!visibleChildren[i]) continue;
      if (resident[i]) {
        ++result_.counters.waitingForSiblings;
      } else {
        // What loading it fixes: this tile's error, seen at the child's distance.
        request(children[i], errorPixels(visible, visibleChildren[i]->distanceMeters));
      }
      lookahead(*visibleChildren[i], options_.lookaheadLevels,
                errorPixels(visible, visibleChildren[i]->distanceMeters) / 4);
    }
  }

  const SelectionView& view_;
  const TileCatalog& catalog_;
  const SelectionOptions& options_;
  const std::unordered_set<geo::TileId> refined_;
  double cameraHeightMeters_ = 0.0;
  double threshold_ = 2.0;
  double hysteresis_ = 0.0;
  SelectionResult result_;
};

}  // namespace

SelectionResult selectTiles(const SelectionView& view, const TileCatalog& catalog,
                            const SelectionOptions& options,
                            const std::vector<geo::TileId>& previousTiles) {
  return Traversal(view, catalog, options, previousTiles).run();
}

}  // namespace globe::terrain
