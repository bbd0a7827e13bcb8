// Tile selection: from a view and the pyramid's catalog to the rendering tile array (the tiles
// to draw this frame, never overlapping, never leaving a hole) and the tiles to load next.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "geo/globe_rectangle.hpp"
#include "geo/tile_id.hpp"
#include "terrain/selection_view.hpp"
#include "terrain/tile_catalog.hpp"

namespace globe::terrain {

// Where something draped over the terrain takes its resolution from the terrain tile's level
// (imagery: terrain/imagery_level.hpp), refining a tile of level <= throughLevel overlapping the
// rectangle makes the drape sharper, so such tiles refine by the nominal error even when the
// selection uses measured ones; elsewhere smooth ground stops refining early as usual.
struct NominalErrorRegion {
  geo::GlobeRectangle rectangle;
  uint32_t throughLevel = 0;
};

struct SelectionOptions {
  // A tile is refined while its geometric error (screen_space_error.hpp) would cover more than
  // this many pixels: cesium-native's default, which with kTerrainQuality = 0.25 draws a tile
  // when its vertices are ~8 pixels apart (~128 pixels per 17-vertex tile). Values that are not
  // > 0 (NaN included) count as 2; +infinity never refines.
  double maximumScreenSpaceErrorPixels = 2.0;
  // A tile drawn last frame refines only above (1 + h) x threshold; a tile refined last frame
  // (some descendant of it was in previousTiles) goes back to drawing only below
  // (1 - h) x threshold. 0.25: refine at 2.5 px, coarsen at 1.5 px, so the camera must move
  // ~1.7x further away before a refinement is undone, and a freshly refined tile's children
  // (~1.25 px) are not themselves refined the next frame. Clamped to [0, 0.9]; NaN counts as 0.
  double hysteresisFraction = 0.25;
  // The pyramid's block size (manifest verticesPerSide): it sets the geometric error per level.
  uint32_t verticesPerSide = 17;
  // Tiles of this level are never refined.
  uint32_t maximumLevel = geo::kMaxLevel;
  // Use the tiler's measured geometric errors (TileSummary, tileGeometricErrorMeters): smooth
  // tiles stop refining early, except inside nominalErrorRegions.
  bool measuredErrors = true;
  std::span<const NominalErrorRegion> nominalErrorRegions;  // not owned: outlives selectTiles
  // Where a tile waits for its children, also request the descendants the refinement will want
  // next, this many levels further (each level at a quarter of the priority): over a network the
  // chain of round trips, one level per frame, is otherwise what a view waits on. They are loads
  // only: what is drawn and the counters are the same. 0: off.
  uint32_t lookaheadLevels = 0;
};

struct TileRequest {
  geo::TileId tile;
  // Higher = sooner. The screen-space error, at this tile's distance, of the tile drawn in its
  // place (its parent): how many pixels loading it would fix. Roots get the largest double.
  double priority = 0.0;
  bool lookahead = false;  // wanted ahead of the refinement, not by this frame's view
};

// Every visited tile (its bounding volume was tested) ends in exactly one of the last six
// counters, so visited == culledByFrustum + culledByHorizon + refined + selected +
// wantedNotResident + waitingForSiblings. selected == tiles.size() and
// wantedNotResident == requests.size().
struct SelectionCounters {
  uint64_t visited = 0;
  uint64_t culledByFrustum = 0;
  uint64_t culledByHorizon = 0;     // inside the frustum but hidden behind the globe
  uint64_t refined = 0;             // replaced by its children
  uint64_t selected = 0;            // drawn
  uint64_t wantedNotResident = 0;   // visible and wanted, not loaded: requested
  uint64_t waitingForSiblings = 0;  // visible and loaded, but a sibling is not: the parent draws
};

struct SelectionResult {
  // The rendering tile array: resident tiles whose rectangles never overlap in area and that
  // cover every visible part of the globe (as long as the roots are resident). Depth-first order.
  std::vector<geo::TileId> tiles;
  // Visible tiles the pyramid has and the selection wants but that are not resident, each once,
  // most important first (priority descending, then coarser level, then TileId).
  std::vector<TileRequest> requests;
  SelectionCounters counters;

  // Nothing wanted is missing: this is the final view for this camera (snapshots wait for it).
  bool complete() const { return counters.wantedNotResident == 0; }
};

// Traverses the quadtree from the two level-0 roots. A visited tile is culled if its bounding
// region (rectangle x subtree height range) is outside the frustum or below the horizon; culled
// tiles are neither drawn nor requested. A visible tile is refined when its screen-space error
// (from the distance lower bound to its region) exceeds the hysteresis threshold, its level is
// below options.maximumLevel and the catalog has its four children; it is then replaced by its
// visible children only if every visible child is resident (a tile whose children are all
// culled is replaced by nothing). Otherwise it draws itself, in place of the wanted children,
// and its non-resident visible children are requested: a parent, resident because the
// traversal only descends into resident tiles, always stands in for missing children, so no
// hole opens. A visible root that is not resident is requested and leaves a hole (nothing
// coarser exists). previousTiles: last frame's tiles, for the hysteresis.
// Cheap enough per frame without caches (bounding volumes are rebuilt: 8 points per tile from
// level 4 on): ~0.1-0.5 ms for the 100-800 tiles visited in the tests' views.
SelectionResult selectTiles(const SelectionView& view, const TileCatalog& catalog,
                            const SelectionOptions& options,
                            const std::vector<geo::TileId>& previousTiles);

}  // namespace globe::terrain
