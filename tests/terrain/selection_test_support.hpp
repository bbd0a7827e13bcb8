// Test support for tile selection: catalogs (the real bundled pyramid, a synthetic one), camera
// views built with glm in double, and brute-force checks of a selection (coverage by ray casting,
// overlap, plausible visibility, counters).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "geo/tile_id.hpp"
#include "streaming/tile_store.hpp"
#include "terrain/selection_view.hpp"
#include "terrain/tile_catalog.hpp"
#include "terrain/tile_selection.hpp"

namespace globe::terrain::testing {

using Residency = std::function<bool(const geo::TileId&)>;

// Deterministic "random" residency: each tile is resident with probability p (fixed per seed).
// Roots are resident when rootsResident is true, whatever p.
Residency randomResidency(uint64_t seed, double probability, bool rootsResident);

// The bundled real pyramid (ETOPO20 + W002N52 + Fuji), tiled once per process, read through
// io::TileStore: find() from TileStore::entry(), isResident() from a settable predicate.
class PyramidCatalog final : public TileCatalog {
 public:
  static PyramidCatalog& bundled();
  std::optional<TileSummary> find(const geo::TileId& tile) const override;
  bool isResident(const geo::TileId& tile) const override;
  void setResidency(Residency residency) { residency_ = std::move(residency); }
  uint32_t verticesPerSide() const { return store_->manifest().verticesPerSide; }
  uint32_t maxLevel() const { return store_->manifest().maxLevel(); }

 private:
  explicit PyramidCatalog(std::unique_ptr<streaming::TileStore> store) : store_(std::move(store)) {}
  std::unique_ptr<streaming::TileStore> store_;
  Residency residency_;
};

// Every tile of levels 0..maxLevel exists with the same height range; residency settable.
class SyntheticCatalog final : public TileCatalog {
 public:
  SyntheticCatalog(uint32_t maxLevel, HeightRange range) : maxLevel_(maxLevel), range_(range) {}
  std::optional<TileSummary> find(const geo::TileId& tile) const override;
  bool isResident(const geo::TileId& tile) const override {
    return !residency_ || residency_(tile);
  }
  void setResidency(Residency residency) { residency_ = std::move(residency); }

 private:
  uint32_t maxLevel_;
  HeightRange range_;
  Residency residency_;
};

struct TestView {
  SelectionView view;
  glm::dmat4 viewProjection{1.0};
  std::string name;
};

// A camera at (lon, lat, height) looking pitchDegrees from straight down (0 = nadir, 90 = the
// horizon), towards headingDegrees (0 = north, 90 = east); 16:9, 60 degree vertical fov, 1080 px.
TestView cameraView(double longitudeDegrees, double latitudeDegrees, double heightMeters,
                    double pitchDegrees, double headingDegrees, const std::string& name);

// Brute-force checks, reported with ADD_FAILURE naming the view; return false on a failure.
struct CoverageStats {
  uint64_t hitsCovered = 0;     // visible ray hits lying in a selected tile
  uint64_t hitsOffTerrain = 0;  // hits outside every drawn tile but provably off the terrain
};
// Casts a columns x rows grid of pixel rays onto the ellipsoid raised by each of several
// heights; every first hit inside the frustum must lie in a selected tile's rectangle, unless
// some catalog tile containing it has a subtree height range excluding the hit's height.
bool checkCoverage(const TestView& view, const TileCatalog& catalog, const SelectionResult& result,
                   CoverageStats* stats = nullptr, int columns = 64, int rows = 36);
// Counters, uniqueness, no overlap, residency, requests (sorted, in the catalog, not resident,
// parent drawn in their place), and every drawn or requested tile plausibly visible.
bool checkInvariants(const TestView& view, const TileCatalog& catalog,
                     const SelectionOptions& options, const SelectionResult& result);

// Distance from the camera to the nearest of a dense sample of the tile's region: an upper
// bound of the true distance, for an independent screen-space error.
double sampledDistanceMeters(const glm::dvec3& cameraEcefMeters, const geo::TileId& tile,
                             const HeightRange& range, const geo::Ellipsoid& ellipsoid);
// The model of screen_space_error.hpp written out again: 0.25 x a x pi / (2^L (N - 1)).
double independentScreenSpaceErrorPixels(const TestView& view, const geo::TileId& tile,
                                         const HeightRange& range, uint32_t verticesPerSide);

// Strict ancestors of the tiles.
std::vector<geo::TileId> ancestorsOf(const std::vector<geo::TileId>& tiles);

}  // namespace globe::terrain::testing
