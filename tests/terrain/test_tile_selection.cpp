// Tests for terrain/tile_selection.hpp on a synthetic catalog (every tile exists, flat): the
// residency rule, roots first, maximum level, the exact hysteresis thresholds, option ranges.
#include "terrain/tile_selection.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <set>

#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "terrain/screen_space_error.hpp"
#include "tests/terrain/selection_test_support.hpp"

namespace globe::terrain {
namespace {

using ::testing::AllOf;
using testing::cameraView;
using ::testing::HasSubstr;
using ::testing::Not;
using testing::SyntheticCatalog;

bool contains(const std::vector<geo::TileId>& tiles, const geo::TileId& tile) {
  return std::find(tiles.begin(), tiles.end(), tile) != tiles.end();
}

bool isStrictDescendant(geo::TileId tile, const geo::TileId& ancestor) {
  while (tile.level > ancestor.level) {
    tile = tile.parent();
    if (tile == ancestor) return true;
  }
  return false;
}

TEST(TileSelection, NothingResidentRequestsTheVisibleRootsFirst) {
  SyntheticCatalog catalog(8, {0, 0});
  catalog.setResidency([](const geo::TileId&) { return false; });
  const SelectionOptions options;
  // Above (0, 0) from 20,000 km both hemispheres' roots are in view.
  const auto both = cameraView(0.0, 0.0, 2e7, 0.0, 0.0, "both roots");
  const SelectionResult r = selectTiles(both.view, catalog, options, {});
  EXPECT_TRUE(r.tiles.empty());
  ASSERT_EQ(r.requests.size(), 2u);
  EXPECT_EQ(r.requests[0].tile, (geo::TileId{0, 0, 0}));
  EXPECT_EQ(r.requests[1].tile, (geo::TileId{0, 1, 0}));
  EXPECT_EQ(r.requests[0].priority, std::numeric_limits<double>::max());
  EXPECT_FALSE(r.complete());
  EXPECT_EQ(r.counters.visited, 2u);
  EXPECT_EQ(r.counters.wantedNotResident, 2u);
  testing::checkInvariants(both, catalog, options, r);

  // Above 90 E from 1,000 km the western hemisphere is behind the globe: culled, not requested.
  const auto east = cameraView(90.0, 0.0, 1e6, 0.0, 0.0, "east root");
  const SelectionResult e = selectTiles(east.view, catalog, options, {});
  ASSERT_EQ(e.requests.size(), 1u);
  EXPECT_EQ(e.requests[0].tile, (geo::TileId{0, 1, 0}));
  EXPECT_EQ(e.counters.culledByFrustum + e.counters.culledByHorizon, 1u);
  testing::checkInvariants(east, catalog, options, e);
}

TEST(TileSelection, AMissingChildKeepsItsParentDrawing) {
  SyntheticCatalog catalog(12, {0, 100});
  const auto view = cameraView(10.0, 45.0, 3e5, 20.0, 0.0, "missing child");
  const SelectionOptions options;
  const SelectionResult full = selectTiles(view.view, catalog, options, {});
  ASSERT_TRUE(full.complete());
  testing::checkInvariants(view, catalog, options, full);
  testing::checkCoverage(view, catalog, full);
  // Knock out the level-6 tile under the camera: its parent draws in its place.
  const geo::TileId missing = *geo::GeographicTilingScheme::positionToTile(
      geo::degreesToRadians(10.0), geo::degreesToRadians(45.0), 6);
  catalog.setResidency([&](const geo::TileId& t) { return t != missing; });
  const SelectionResult r = selectTiles(view.view, catalog, options, {});
  EXPECT_FALSE(r.complete());
  EXPECT_TRUE(contains(r.tiles, missing.parent()));
  ASSERT_EQ(r.requests.size(), 1u);
  EXPECT_EQ(r.requests[0].tile, missing);
  EXPECT_GE(r.counters.waitingForSiblings, 1u);  // its visible siblings are loaded but unused
  for (const geo::TileId& t : r.tiles) EXPECT_FALSE(isStrictDescendant(t, missing.parent()));
  testing::checkInvariants(view, catalog, options, r);
  testing::checkCoverage(view, catalog, r);
}

TEST(TileSelection, NeverRefinesBeyondTheMaximumLevelOrThePyramid) {
  SyntheticCatalog catalog(9, {0, 0});
  const auto view = cameraView(-70.0, -33.0, 10.0, 45.0, 200.0, "low");
  SelectionOptions options;
  const SelectionResult pyramid = selectTiles(view.view, catalog, options, {});
  uint32_t deepest = 0;
  for (const auto& t : pyramid.tiles) deepest = std::max(deepest, t.level);
  EXPECT_EQ(deepest, 9u);  // the pyramid's leaves
  testing::checkInvariants(view, catalog, options, pyramid);
  options.maximumLevel = 5;
  const SelectionResult capped = selectTiles(view.view, catalog, options, {});
  deepest = 0;
  for (const auto& t : capped.tiles) deepest = std::max(deepest, t.level);
  EXPECT_EQ(deepest, 5u);
  testing::checkInvariants(view, catalog, options, capped);
  testing::checkCoverage(view, catalog, capped);
}

// The screen-space error of a tile straight below the camera, as the selection computes it.
double errorBelow(const testing::TestView& view, const geo::TileId& tile,
                  const HeightRange& range) {
  const auto rect = geo::GeographicTilingScheme::tileRectangle(tile);
  const auto volume = geo::RegionVolume::fromRegion(
      {rect, static_cast<double>(range.minimumMeters), static_cast<double>(range.maximumMeters)},
      view.view.ellipsoid);
  const double height =
      geo::ecefToCartographic(view.view.ellipsoid, view.view.cameraEcefMeters)->heightMeters;
  return screenSpaceErrorPixels(
      geometricErrorMeters(tile.level, 17, view.view.ellipsoid),
      distanceLowerBoundMeters(view.view.cameraEcefMeters, height, volume), view.view);
}

TEST(TileSelection, HysteresisRefinesAboveAndCoarsensBelowTheDocumentedThresholds) {
  const HeightRange flat{0, 0};
  SyntheticCatalog catalog(20, flat);
  const geo::TileId tile{10, 1300, 300};
  const geo::Cartographic centre = geo::GeographicTilingScheme::tileRectangle(tile).center();
  const auto viewWithError = [&](double pixels) {
    // SSE ~ 1/height: solve for the height, then correct once for the exact bound.
    double height = 1e4;
    for (int i = 0; i < 30; ++i) {
      const auto v = cameraView(centre.longitudeDegrees(), centre.latitudeDegrees(), height, 0.0,
                                0.0, "hysteresis");
      height *= errorBelow(v, tile, flat) / pixels;
    }
    return cameraView(centre.longitudeDegrees(), centre.latitudeDegrees(), height, 0.0, 0.0,
                      "hysteresis at " + std::to_string(pixels) + " px");
  };
  const std::array<geo::TileId, 4> children = tile.children();
  const std::vector<geo::TileId> refinedBefore(children.begin(), children.end());
  const std::vector<geo::TileId> drawnBefore{tile};
  struct Case {
    double pixels;
    double hysteresis;
    const std::vector<geo::TileId>* previous;
    bool refined;
  };
  const Case cases[] = {
      {2.45, 0.25, &drawnBefore, false},  {2.55, 0.25, &drawnBefore, true},
      {2.45, 0.25, nullptr, false},       {2.55, 0.25, nullptr, true},
      {1.55, 0.25, &refinedBefore, true}, {1.45, 0.25, &refinedBefore, false},
      {1.95, 0.0, &drawnBefore, false},   {2.05, 0.0, &drawnBefore, true},
      {1.95, 0.0, &refinedBefore, false}, {2.05, 0.0, &refinedBefore, true},
  };
  for (const Case& c : cases) {
    const auto view = viewWithError(c.pixels);
    ASSERT_NEAR(errorBelow(view, tile, flat), c.pixels, 1e-6);
    SelectionOptions options;
    options.hysteresisFraction = c.hysteresis;
    const std::vector<geo::TileId> none;
    const SelectionResult r =
        selectTiles(view.view, catalog, options, c.previous ? *c.previous : none);
    EXPECT_EQ(contains(r.tiles, tile), !c.refined) << view.name << " h " << c.hysteresis;
    EXPECT_EQ(contains(r.tiles, tile.children()[0]), c.refined) << view.name;
    testing::checkInvariants(view, catalog, options, r);
  }
}

TEST(TileSelection, OptionsOutOfRangeAreSanitised) {
  SyntheticCatalog catalog(14, {-50, 900});
  const auto view = cameraView(25.0, 60.0, 3000.0, 70.0, 30.0, "options");
  const auto tilesWith = [&](double threshold, double hysteresis) {
    SelectionOptions options;
    options.maximumScreenSpaceErrorPixels = threshold;
    options.hysteresisFraction = hysteresis;
    return selectTiles(view.view, catalog, options, {}).tiles;
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto reference = tilesWith(2.0, 0.25);
  EXPECT_EQ(tilesWith(nan, 0.25), reference);
  EXPECT_EQ(tilesWith(0.0, 0.25), reference);
  EXPECT_EQ(tilesWith(-3.0, 0.25), reference);
  // +inf never refines: only roots are drawn (the western one is only conservatively visible).
  const auto never = tilesWith(std::numeric_limits<double>::infinity(), 0.25);
  EXPECT_TRUE(std::find(never.begin(), never.end(), geo::TileId{0, 1, 0}) != never.end());
  for (const geo::TileId& t : never) EXPECT_EQ(t.level, 0u);
  EXPECT_EQ(tilesWith(2.0, nan), tilesWith(2.0, 0.0));
  EXPECT_EQ(tilesWith(2.0, -1.0), tilesWith(2.0, 0.0));
  EXPECT_EQ(tilesWith(2.0, 7.0), tilesWith(2.0, 0.9));
  EXPECT_NE(tilesWith(8.0, 0.0), tilesWith(2.0, 0.0));  // the threshold does matter
}

// The messages of the failures the call reports, intercepted (they do not fail the test).
std::string failuresOf(const std::function<void()>& call) {
  ::testing::TestPartResultArray results;
  {
    const ::testing::ScopedFakeTestPartResultReporter reporter(
        ::testing::ScopedFakeTestPartResultReporter::INTERCEPT_ONLY_CURRENT_THREAD, &results);
    call();
  }
  std::string messages;
  for (int i = 0; i < results.size(); ++i) messages += results.GetTestPartResult(i).message();
  return messages;
}

// The brute-force checks used on every selection catch fabricated mistakes.
TEST(TileSelection, TheBruteForceChecksCatchFabricatedMistakes) {
  SyntheticCatalog catalog(12, {0, 100});
  const auto view = cameraView(10.0, 45.0, 3e5, 20.0, 0.0, "fabricated");
  const SelectionOptions options;
  const SelectionResult good = selectTiles(view.view, catalog, options, {});
  ASSERT_TRUE(testing::checkInvariants(view, catalog, options, good));
  ASSERT_TRUE(testing::checkCoverage(view, catalog, good));

  const auto nadir = [&](uint32_t level) {
    return *geo::GeographicTilingScheme::positionToTile(geo::degreesToRadians(10.0),
                                                        geo::degreesToRadians(45.0), level);
  };
  SelectionResult holed = good;
  const auto below = std::find_if(holed.tiles.begin(), holed.tiles.end(),
                                  [&](const auto& t) { return t == nadir(t.level); });
  ASSERT_NE(below, holed.tiles.end());
  holed.tiles.erase(below);
  --holed.counters.selected;
  --holed.counters.visited;
  EXPECT_THAT(failuresOf([&] { testing::checkCoverage(view, catalog, holed); }),
              HasSubstr("hole at"));
  EXPECT_EQ(failuresOf([&] { testing::checkInvariants(view, catalog, options, holed); }), "");

  SelectionResult overlapping = good;
  overlapping.tiles.push_back(good.tiles.front().parent());
  ++overlapping.counters.selected;
  ++overlapping.counters.visited;
  EXPECT_THAT(failuresOf([&] { testing::checkInvariants(view, catalog, options, overlapping); }),
              AllOf(HasSubstr("inside"), HasSubstr("overlaps"), Not(HasSubstr("c.visited"))));

  SelectionResult farSide = good;
  farSide.tiles.push_back(*geo::GeographicTilingScheme::positionToTile(
      geo::degreesToRadians(-170.0), geo::degreesToRadians(-45.0), 8));
  ++farSide.counters.selected;
  ++farSide.counters.visited;
  EXPECT_THAT(failuresOf([&] { testing::checkInvariants(view, catalog, options, farSide); }),
              HasSubstr("drew invisible"));

  SelectionResult miscounted = good;
  ++miscounted.counters.visited;
  EXPECT_THAT(failuresOf([&] { testing::checkInvariants(view, catalog, options, miscounted); }),
              HasSubstr("c.visited"));
}

}  // namespace
}  // namespace globe::terrain

namespace globe::terrain {
namespace {

// Lookahead (for remote pyramids): with only the coarse levels resident, the tiles the full
// refinement will draw, and their ancestors, are requested up to 1 + lookaheadLevels below what
// is resident, each under a tile already requested; what is drawn and every counter stay the
// same. (A requested tile may still draw nothing: its bounding volume is visible while every
// child's tighter one is culled, as for the plain requests.)
TEST(TileSelection, LookaheadRequestsExactlyWhatTheRefinementWillWant) {
  SyntheticCatalog catalog(12, {0, 100});
  const auto view = testing::cameraView(10.0, 45.0, 3e4, 20.0, -30.0, "lookahead");
  SelectionOptions options;
  const SelectionResult full = selectTiles(view.view, catalog, options, {});
  ASSERT_TRUE(full.complete());
  catalog.setResidency([](const geo::TileId& t) { return t.level <= 3; });
  const SelectionResult plain = selectTiles(view.view, catalog, options, {});
  options.lookaheadLevels = 3;
  const SelectionResult ahead = selectTiles(view.view, catalog, options, {});

  EXPECT_EQ(ahead.tiles, plain.tiles);
  EXPECT_EQ(ahead.counters.visited, plain.counters.visited);
  EXPECT_EQ(ahead.counters.wantedNotResident, plain.counters.wantedNotResident);
  std::set<geo::TileId> wanted;  // what the full refinement draws, and every ancestor of it
  for (const geo::TileId& t : full.tiles) {
    for (geo::TileId a = t;; a = a.parent()) {
      wanted.insert(a);
      if (a.level == 0) break;
    }
  }
  std::set<geo::TileId> requested;
  for (const TileRequest& r : ahead.requests) requested.insert(r.tile);
  for (const TileRequest& r : plain.requests) EXPECT_TRUE(requested.contains(r.tile));
  EXPECT_GT(requested.size(), plain.requests.size());
  for (const geo::TileId& t : requested) {
    EXPECT_GE(t.level, 4u);
    EXPECT_LE(t.level, 7u);
    if (t.level > 4) {
      EXPECT_TRUE(requested.contains(t.parent())) << geo::tileName(t);
    }
  }
  for (const geo::TileId& t : wanted) {
    if (t.level >= 4 && t.level <= 7) {
      EXPECT_TRUE(requested.contains(t)) << geo::tileName(t);
    }
  }
}

}  // namespace
}  // namespace globe::terrain
