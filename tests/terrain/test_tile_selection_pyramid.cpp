// Tile selection on the real bundled pyramid (ETOPO20 + W002N52 + Fuji at level 14): coverage
// without holes or overlaps along a zoom onto Mount Fuji, over the poles and across the
// antimeridian, the screen-space error criterion, hysteresis, and partial residency.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>

#include "geo/bounding_region.hpp"
#include "geo/frustum.hpp"
#include "geo/tiling_scheme.hpp"
#include "terrain/tile_selection.hpp"
#include "tests/terrain/selection_test_support.hpp"

namespace globe::terrain {
namespace {

using testing::cameraView;
using testing::PyramidCatalog;
using testing::TestView;

constexpr double kFujiLongitude = 138.7275;
constexpr double kFujiLatitude = 35.3606;
constexpr double kFujiSummitMeters = 3776.0;

uint32_t deepestLevel(const std::vector<geo::TileId>& tiles) {
  uint32_t deepest = 0;
  for (const geo::TileId& t : tiles) deepest = std::max(deepest, t.level);
  return deepest;
}

// 20,000 km down to 2 m above the summit, halving the height each frame.
std::vector<double> zoomHeightsAboveSummit() {
  std::vector<double> heights;
  for (double d = 2e7; d > 3.0; d /= 2.0) heights.push_back(d);
  heights.push_back(2.0);
  return heights;
}

// A pitch above ~0.8 of the globe's angular radius would look past it from high up.
TestView fujiView(double heightAboveSummit, double pitchDegrees) {
  const double radius = 6371e3;
  pitchDegrees = std::min(
      pitchDegrees, 0.8 * geo::radiansToDegrees(std::asin(radius / (radius + heightAboveSummit))));
  char name[96];
  std::snprintf(name, sizeof name, "Fuji +%.0f m pitch %.0f", heightAboveSummit, pitchDegrees);
  return cameraView(kFujiLongitude, kFujiLatitude, kFujiSummitMeters + heightAboveSummit,
                    pitchDegrees, 20.0, name);
}

// Runs the zoom as consecutive frames (previous tiles fed back) and checks every frame.
std::vector<SelectionResult> zoom(double pitchDegrees, const char* label) {
  PyramidCatalog& catalog = PyramidCatalog::bundled();
  const SelectionOptions options;
  std::vector<SelectionResult> frames;
  std::vector<geo::TileId> previous;
  std::printf("%s\n%12s %6s %5s %7s %7s %7s %6s %8s %7s\n", label, "height_m", "tiles", "level",
              "visited", "frustum", "horizon", "reqs", "hits", "ms");
  for (const double d : zoomHeightsAboveSummit()) {
    const TestView view = fujiView(d, pitchDegrees);
    const auto start = std::chrono::steady_clock::now();
    SelectionResult r = selectTiles(view.view, catalog, options, previous);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    testing::checkInvariants(view, catalog, options, r);
    testing::CoverageStats stats;
    testing::checkCoverage(view, catalog, r, &stats);
    EXPECT_GT(stats.hitsCovered, 1000u) << view.name;
    const SelectionCounters& c = r.counters;
    std::printf("%12.0f %6zu %5u %7llu %7llu %7llu %6zu %8llu %7.2f\n", d, r.tiles.size(),
                deepestLevel(r.tiles), static_cast<unsigned long long>(c.visited),
                static_cast<unsigned long long>(c.culledByFrustum),
                static_cast<unsigned long long>(c.culledByHorizon), r.requests.size(),
                static_cast<unsigned long long>(stats.hitsCovered), ms);
    previous = r.tiles;
    frames.push_back(std::move(r));
  }
  return frames;
}

TEST(TileSelectionPyramid, ZoomOntoFujiLookingDownCoversEveryFrameAndReachesTheDeepLevels) {
  const auto frames = zoom(0.0, "zoom onto Fuji, looking down, everything resident");
  EXPECT_LE(deepestLevel(frames.front().tiles), 3u);  // from 20,000 km: coarse
  EXPECT_GE(deepestLevel(frames.back().tiles), 13u);  // 2 m above the summit: the Fuji levels
  for (const auto& f : frames) EXPECT_TRUE(f.complete());
}

TEST(TileSelectionPyramid, ZoomOntoFujiObliquelyCoversEveryFrame) {
  const auto frames = zoom(60.0, "zoom onto Fuji, 60 degrees from nadir, everything resident");
  EXPECT_LE(deepestLevel(frames.front().tiles), 3u);
  EXPECT_GE(deepestLevel(frames.back().tiles), 13u);
  // Looking at the horizon from near the ground, the far side of the globe is culled by the
  // horizon and the rest by the frustum.
  EXPECT_GT(frames.back().counters.culledByHorizon, 0u);
  EXPECT_GT(frames.back().counters.culledByFrustum, 0u);
}

TEST(TileSelectionPyramid, ZoomOntoFujiPartlyResidentNeverLeavesAHole) {
  PyramidCatalog& catalog = PyramidCatalog::bundled();
  const SelectionOptions options;
  int incomplete = 0;
  for (const double pitch : {0.0, 60.0}) {
    for (int mode = 0; mode < 3; ++mode) {
      if (mode == 0) catalog.setResidency([](const geo::TileId& t) { return t.level <= 6; });
      if (mode == 1) catalog.setResidency(testing::randomResidency(7, 0.6, true));
      if (mode == 2) catalog.setResidency(testing::randomResidency(8, 0.95, true));
      std::vector<geo::TileId> previous;
      for (const double d : zoomHeightsAboveSummit()) {
        TestView view = fujiView(d, pitch);
        view.name += " residency " + std::to_string(mode);
        const SelectionResult r = selectTiles(view.view, catalog, options, previous);
        testing::checkInvariants(view, catalog, options, r);
        testing::checkCoverage(view, catalog, r);
        incomplete += r.complete() ? 0 : 1;
        previous = r.tiles;
      }
    }
  }
  EXPECT_GT(incomplete, 20);  // the partial residency did bite
}

std::vector<TestView> polarAndAntimeridianViews() {
  return {
      cameraView(0.0, 90.0, 1e6, 0.0, 0.0, "north pole, 1000 km, down"),
      cameraView(30.0, 89.99, 3000.0, 0.0, 0.0, "north pole, 3 km, down"),
      cameraView(-100.0, 84.0, 2e5, 60.0, 0.0, "across the north pole, 200 km"),
      cameraView(0.0, -90.0, 2e6, 0.0, 0.0, "south pole, 2000 km, down"),
      cameraView(45.0, -89.995, 4000.0, 30.0, 180.0, "south pole, 4 km over the ice"),
      cameraView(170.0, -80.0, 5e4, 70.0, 180.0, "towards the south pole, 50 km"),
      cameraView(180.0, 0.0, 5e5, 0.0, 0.0, "antimeridian, 500 km, down"),
      cameraView(179.99, -17.0, 2000.0, 75.0, 90.0, "across the antimeridian eastwards, Fiji"),
      cameraView(-179.995, 65.5, 300.0, 80.0, 270.0, "across the antimeridian westwards, Bering"),
      cameraView(-180.0, 89.0, 1e4, 45.0, 0.0, "antimeridian and pole"),
  };
}

TEST(TileSelectionPyramid, PolesAndTheAntimeridianAreCoveredWithoutGaps) {
  PyramidCatalog& catalog = PyramidCatalog::bundled();
  const SelectionOptions options;
  for (int mode = 0; mode < 3; ++mode) {
    if (mode == 1) catalog.setResidency(testing::randomResidency(11, 0.5, true));
    if (mode == 2) catalog.setResidency([](const geo::TileId& t) { return t.level <= 3; });
    for (TestView view : polarAndAntimeridianViews()) {
      view.name += " residency " + std::to_string(mode);
      const SelectionResult r = selectTiles(view.view, catalog, options, {});
      testing::checkInvariants(view, catalog, options, r);
      testing::CoverageStats stats;
      testing::checkCoverage(view, catalog, r, &stats);
      EXPECT_GT(stats.hitsCovered, 1000u) << view.name;
      if (mode == 0) {
        EXPECT_TRUE(r.complete()) << view.name;
        // Tiles on both sides of the seam or around the pole are drawn.
        std::set<uint32_t> columns;
        for (const auto& t : r.tiles) columns.insert(t.x >> t.level);  // the level-0 root
        if (view.name.find("antimeridian") != std::string::npos ||
            view.name.find("across the north") != std::string::npos) {
          EXPECT_EQ(columns.size(), 2u) << view.name;
        }
      }
    }
  }
}

// With everything resident: every drawn tile that could refine has an error (measured
// independently, with a sampled distance) within the refinement threshold, and every refined
// tile's error is not far below it.
TEST(TileSelectionPyramid, DrawnTilesMeetTheScreenSpaceErrorCriterion) {
  PyramidCatalog& catalog = PyramidCatalog::bundled();
  SelectionOptions options;
  options.measuredErrors = false;  // the independent model is the nominal one
  double smallestRefinedRatio = 1e300;
  size_t checkedDrawn = 0;
  for (const double hysteresis : {0.0, 0.25}) {
    options.hysteresisFraction = hysteresis;
    const double limit = options.maximumScreenSpaceErrorPixels * (1.0 + hysteresis);
    for (const double d : {2e6, 2e5, 2e4, 2e3, 200.0, 20.0}) {
      for (const double pitch : {0.0, 45.0, 75.0}) {
        const TestView view = fujiView(d, pitch);
        const SelectionResult r = selectTiles(view.view, catalog, options, {});
        ASSERT_TRUE(r.complete());
        for (const geo::TileId& t : r.tiles) {
          const auto summary = catalog.find(t);
          if (t.level >= options.maximumLevel || !catalog.find(t.children()[0])) continue;
          ++checkedDrawn;
          const double sse = testing::independentScreenSpaceErrorPixels(
              view, t, summary->subtreeHeightRange, catalog.verticesPerSide());
          EXPECT_LE(sse, limit) << view.name << " tile " << t.level << "/" << t.x << "/" << t.y;
        }
        for (const geo::TileId& t : testing::ancestorsOf(r.tiles)) {
          const auto summary = catalog.find(t);
          const double sse = testing::independentScreenSpaceErrorPixels(
              view, t, summary->subtreeHeightRange, catalog.verticesPerSide());
          smallestRefinedRatio = std::min(smallestRefinedRatio, sse / limit);
        }
      }
    }
  }
  EXPECT_GT(checkedDrawn, 1000u);
  // The distance bound is conservative but not loose: refined tiles were truly near the limit.
  EXPECT_GT(smallestRefinedRatio, 0.9);
  std::printf("smallest (independent SSE / limit) of a refined tile: %.3f\n", smallestRefinedRatio);
}

// The tiler's measured errors (opt-in): where the ground is smoother than the nominal error
// assumes, tiles stop refining sooner (down to half the nominal error: kMeasuredErrorFloor), and
// the selection keeps every invariant and covers the view.
TEST(TileSelectionPyramid, MeasuredErrorsDrawFewerTilesWhereTheGroundIsFlat) {
  PyramidCatalog& catalog = PyramidCatalog::bundled();
  struct Case {
    TestView view;
    double largestRatio;  // measured / nominal tile count at most
  };
  const Case cases[] = {
      {cameraView(-1.0, 52.6, 800.0, 80.0, 80.0, "east England, low and oblique"), 0.9},
      {cameraView(-150.0, 20.0, 3000.0, 60.0, 0.0, "open Pacific"), 1.0},
      {cameraView(138.73, 35.36, 6000.0, 70.0, 30.0, "Fuji's flanks"), 0.8},
  };
  for (const Case& c : cases) {
    SelectionOptions nominal;
    nominal.measuredErrors = false;
    const SelectionResult before = selectTiles(c.view.view, catalog, nominal, {});
    SelectionOptions measured;
    measured.measuredErrors = true;
    const SelectionResult after = selectTiles(c.view.view, catalog, measured, {});
    ASSERT_TRUE(before.complete() && after.complete()) << c.view.name;
    EXPECT_TRUE(testing::checkInvariants(c.view, catalog, measured, after));
    EXPECT_TRUE(testing::checkCoverage(c.view, catalog, after));
    const double ratio =
        static_cast<double>(after.tiles.size()) / static_cast<double>(before.tiles.size());
    EXPECT_LE(ratio, c.largestRatio)
        << c.view.name << ": " << before.tiles.size() << " -> " << after.tiles.size() << " tiles";
    std::printf("%s: %zu -> %zu tiles\n", c.view.name.c_str(), before.tiles.size(),
                after.tiles.size());
  }
}

// Under a nominal-error region (a draped layer whose imagery follows the terrain's level) tiles
// of its levels refine as with nominal errors; outside it, and below its deepest level, the
// measured errors still apply. The region over the whole view through a deep level gives the
// nominal selection exactly; one far away, or through a level coarser than the view's, the
// measured selection exactly; one over half the view lies between, with the measured selection
// outside its rectangle.
TEST(TileSelectionPyramid, NominalErrorRegionsRefineAsNominalInsideAndMeasuredOutside) {
  PyramidCatalog& catalog = PyramidCatalog::bundled();
  const TestView view = cameraView(138.73, 35.36, 6000.0, 70.0, 30.0, "Fuji's flanks");
  SelectionOptions nominal;
  nominal.measuredErrors = false;
  SelectionOptions measured;
  const SelectionResult nominalTiles = selectTiles(view.view, catalog, nominal, {});
  const SelectionResult measuredTiles = selectTiles(view.view, catalog, measured, {});
  ASSERT_LT(measuredTiles.tiles.size(), nominalTiles.tiles.size());

  auto withRegion = [&](const geo::GlobeRectangle& rectangle, uint32_t throughLevel) {
    const std::vector<NominalErrorRegion> regions{{rectangle, throughLevel}};
    SelectionOptions options;
    options.nominalErrorRegions = regions;
    SelectionResult result = selectTiles(view.view, catalog, options, {});
    EXPECT_TRUE(result.complete());
    EXPECT_TRUE(testing::checkInvariants(view, catalog, options, result));
    EXPECT_TRUE(testing::checkCoverage(view, catalog, result));
    return result.tiles;
  };
  const auto world = geo::GlobeRectangle::fromDegrees(-180, -90, 180, 90);
  EXPECT_EQ(withRegion(world, geo::kMaxLevel), nominalTiles.tiles);
  EXPECT_EQ(withRegion(geo::GlobeRectangle::fromDegrees(-10, -10, 10, 10), geo::kMaxLevel),
            measuredTiles.tiles);
  EXPECT_EQ(withRegion(world, 3), measuredTiles.tiles);  // no level <= 3 is drawn or near the limit

  // East of Fuji's summit only: more tiles than measured, fewer than nominal, and every tile
  // lies between the two (at or below a measured tile, at or above a nominal one): the region
  // only adds refinement, and only as far as the nominal error goes.
  const double boundaryDegrees = 138.73;
  const auto half =
      withRegion(geo::GlobeRectangle::fromDegrees(boundaryDegrees, -90, 180, 90), geo::kMaxLevel);
  EXPECT_GT(half.size(), measuredTiles.tiles.size());
  EXPECT_LT(half.size(), nominalTiles.tiles.size());
  const std::set<geo::TileId> measuredSet(measuredTiles.tiles.begin(), measuredTiles.tiles.end());
  std::set<geo::TileId> nominalAtOrBelow(nominalTiles.tiles.begin(), nominalTiles.tiles.end());
  for (const geo::TileId& t : testing::ancestorsOf(nominalTiles.tiles)) nominalAtOrBelow.insert(t);
  auto atOrBelowMeasured = [&](geo::TileId tile) {
    for (;;) {
      if (measuredSet.contains(tile)) return true;
      if (tile.level == 0) return false;
      tile = tile.parent();
    }
  };
  size_t differentWest = 0, differentEast = 0;
  for (const geo::TileId& tile : half) {
    EXPECT_TRUE(atOrBelowMeasured(tile)) << tile.level << "/" << tile.x << "/" << tile.y;
    EXPECT_TRUE(nominalAtOrBelow.contains(tile)) << tile.level << "/" << tile.x << "/" << tile.y;
    if (measuredSet.contains(tile)) continue;
    const geo::GlobeRectangle r = geo::GeographicTilingScheme::tileRectangle(tile);
    const bool west = r.eastRadians * 180.0 / std::numbers::pi < boundaryDegrees;
    (west ? differentWest : differentEast) += 1;
  }
  // The refinement the region adds is east of the boundary, bar the children of tiles that
  // straddle it.
  EXPECT_GT(differentEast, 4 * differentWest) << differentEast << " east, " << differentWest;
}

// Level-of-detail flips between two frames: tiles drawn in one and refined in the other (tiles
// entering or leaving the view do not count).
size_t lodFlips(const std::vector<geo::TileId>& a, const std::vector<geo::TileId>& b) {
  const auto refinedA = testing::ancestorsOf(a);
  const auto refinedB = testing::ancestorsOf(b);
  const std::set<geo::TileId> setA(refinedA.begin(), refinedA.end());
  const std::set<geo::TileId> setB(refinedB.begin(), refinedB.end());
  size_t flips = 0;
  for (const auto& t : a) flips += setB.contains(t) ? 1 : 0;
  for (const auto& t : b) flips += setA.contains(t) ? 1 : 0;
  return flips;
}

TEST(TileSelectionPyramid, HysteresisStopsTilesFlippingEveryFrame) {
  PyramidCatalog& catalog = PyramidCatalog::bundled();
  SelectionOptions noHysteresis;
  noHysteresis.hysteresisFraction = 0.0;
  // Find a height where, without hysteresis, 2% up or down changes the level of detail.
  double flipHeight = 0;
  for (double d = 3e4; d < 3e5 && flipHeight == 0; d *= 1.03) {
    const auto low = selectTiles(fujiView(d * 0.98, 30.0).view, catalog, noHysteresis, {});
    const auto high = selectTiles(fujiView(d * 1.02, 30.0).view, catalog, noHysteresis, {});
    if (lodFlips(low.tiles, high.tiles) > 0) flipHeight = d;
  }
  ASSERT_GT(flipHeight, 0.0);
  for (const double h : {0.0, 0.25}) {
    SelectionOptions options;
    options.hysteresisFraction = h;
    std::vector<geo::TileId> previous;
    int flippingFrames = 0;
    for (int frame = 0; frame < 12; ++frame) {
      const TestView view = fujiView(flipHeight * (frame % 2 == 0 ? 0.98 : 1.02), 30.0);
      const SelectionResult r = selectTiles(view.view, catalog, options, previous);
      testing::checkInvariants(view, catalog, options, r);
      if (frame >= 2 && lodFlips(r.tiles, previous) > 0) ++flippingFrames;
      previous = r.tiles;
    }
    std::printf("hysteresis %.2f: %d of 10 oscillating frames (+-2%% around %.0f m) flip tiles\n",
                h, flippingFrames, flipHeight);
    EXPECT_EQ(flippingFrames, h == 0.0 ? 10 : 0);
  }
}

bool isVisible(const TestView& view, const TileCatalog& catalog, const geo::TileId& tile) {
  const auto summary = catalog.find(tile);
  const HeightRange& range = summary->subtreeHeightRange;
  const auto volume = geo::RegionVolume::fromRegion(
      {geo::GeographicTilingScheme::tileRectangle(tile), static_cast<double>(range.minimumMeters),
       static_cast<double>(range.maximumMeters)},
      view.view.ellipsoid);
  return geo::cullRegion(view.view.frustum, volume) != geo::CullResult::Outside &&
         !geo::isBelowHorizon(view.view.cameraEcefMeters, volume);
}

// What the fully resident selection needs resident: the tiles it draws (W), those it refines
// into them (A), and visible tiles it refines into nothing but culled children (children of A
// and roots outside W and A that pass culling, and their visible descendants).
std::set<geo::TileId> neededTiles(const TestView& view, const TileCatalog& catalog,
                                  const SelectionResult& ideal) {
  std::set<geo::TileId> needed(ideal.tiles.begin(), ideal.tiles.end());
  const auto refined = testing::ancestorsOf(ideal.tiles);
  needed.insert(refined.begin(), refined.end());
  std::vector<geo::TileId> stack;
  for (const geo::TileId root : {geo::TileId{0, 0, 0}, geo::TileId{0, 1, 0}}) {
    if (!needed.contains(root)) stack.push_back(root);
  }
  for (const auto& a : refined) {
    for (const auto& c : a.children()) {
      if (!needed.contains(c)) stack.push_back(c);
    }
  }
  while (!stack.empty()) {
    const geo::TileId c = stack.back();
    stack.pop_back();
    if (!isVisible(view, catalog, c)) continue;
    needed.insert(c);
    for (const auto& g : c.children()) {
      if (catalog.find(g)) stack.push_back(g);
    }
  }
  return needed;
}

// Against the fully resident selection of the same view and the tiles it needs (see
// neededTiles): with any residency the selection draws and requests only needed tiles, and it
// is complete exactly when every needed tile is resident (it then draws what the ideal draws).
TEST(TileSelectionPyramid, RandomResidencyFallsBackToAncestorsAndReportsCompleteness) {
  PyramidCatalog& catalog = PyramidCatalog::bundled();
  const SelectionOptions options;
  const std::vector<TestView> views = {fujiView(2000.0, 70.0), fujiView(50.0, 0.0),
                                       cameraView(-1.5, 51.5, 8000.0, 65.0, 300.0, "Wales"),
                                       cameraView(0.0, 90.0, 1e5, 50.0, 0.0, "north pole")};
  int completeRuns = 0, incompleteRuns = 0;
  for (const TestView& base : views) {
    catalog.setResidency(nullptr);
    const SelectionResult ideal = selectTiles(base.view, catalog, options, {});
    ASSERT_TRUE(ideal.complete());
    const std::set<geo::TileId> wanted = neededTiles(base, catalog, ideal);
    std::vector<geo::TileId> wantedList;  // roots stay resident below
    for (const auto& t : wanted) {
      if (t.level > 0) wantedList.push_back(t);
    }
    for (uint64_t seed = 1; seed <= 10; ++seed) {
      testing::Residency residency;
      if (seed <= 6) {
        residency = testing::randomResidency(seed, seed <= 3 ? 0.5 : 0.9, true);
      } else if (seed <= 8) {
        // Everything wanted resident, plenty else missing: complete.
        const auto noise = testing::randomResidency(seed, 0.3, true);
        residency = [&wanted, noise](const geo::TileId& t) {
          return wanted.contains(t) || noise(t);
        };
      } else {
        // Everything resident but one wanted tile: incomplete.
        const geo::TileId gone = wantedList[(seed * 7919) % wantedList.size()];
        residency = [gone](const geo::TileId& t) { return t != gone; };
      }
      catalog.setResidency(residency);
      TestView view = base;
      view.name += " seed " + std::to_string(seed);
      const SelectionResult r = selectTiles(view.view, catalog, options, {});
      testing::checkInvariants(view, catalog, options, r);
      testing::checkCoverage(view, catalog, r);
      const bool allWantedResident =
          std::all_of(wanted.begin(), wanted.end(), [&](const auto& t) { return residency(t); });
      EXPECT_EQ(r.complete(), allWantedResident) << view.name;
      if (r.complete()) {
        EXPECT_EQ(r.tiles, ideal.tiles) << view.name;
        ++completeRuns;
      } else {
        ++incompleteRuns;
      }
      for (const auto& t : r.tiles) EXPECT_TRUE(wanted.contains(t)) << view.name;
      for (const auto& q : r.requests) EXPECT_TRUE(wanted.contains(q.tile)) << view.name;
    }
  }
  EXPECT_GE(completeRuns, 8);
  EXPECT_GE(incompleteRuns, 8);
  catalog.setResidency(nullptr);
}

TEST(TileSelectionPyramid, MissingRootsLeaveOnlyTheirOwnHole) {
  PyramidCatalog& catalog = PyramidCatalog::bundled();
  const SelectionOptions options;
  catalog.setResidency([](const geo::TileId& t) { return !(t.level == 0 && t.x == 0); });
  const TestView view = cameraView(0.0, 0.0, 2e7, 0.0, 0.0, "western root missing");
  const SelectionResult r = selectTiles(view.view, catalog, options, {});
  testing::checkInvariants(view, catalog, options, r);
  ASSERT_FALSE(r.requests.empty());
  EXPECT_EQ(r.requests.front().tile, (geo::TileId{0, 0, 0}));
  EXPECT_EQ(r.requests.size(), 1u);
  for (const auto& t : r.tiles) EXPECT_EQ(t.x >> t.level, 1u);  // all in the eastern hemisphere
  catalog.setResidency(nullptr);
}

}  // namespace
}  // namespace globe::terrain
