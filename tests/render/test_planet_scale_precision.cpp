// Planet-scale float precision where longitude wraps and meridians converge: a camera 1 m above
// synthetic level-20 tiles at (179.999°, 89.99°), 1.1 km from the North Pole, moves in 1 mm steps,
// and the image follows smoothly, as it does over the same scene near (0°, 0°). A
// renderer holding ECEF in float (0.5 m steps at 6.4e6 m) would freeze and then jump; the last test
// shows that the checks catch that.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "terrain/block_grid.hpp"
#include "tests/render/render_test_support.hpp"
#include "tests/support/test_constants.hpp"

namespace globe::render::test {
namespace {

constexpr uint32_t kFineLevel = 20;
using globe::test::kN;

struct Place {
  const char* name;
  double longitudeDegrees, latitudeDegrees;
};
constexpr Place kNearZero{"near_0_0", 0.001, 0.001};
constexpr Place kAntimeridianPole{"antimeridian_pole", 179.999, 89.99};

uint64_t mix(uint64_t value) {  // splitmix64's finaliser
  value = (value ^ (value >> 30)) * 0xBF58476D1CE4E5B9ULL;
  value = (value ^ (value >> 27)) * 0x94D049BB133111EBULL;
  return value ^ (value >> 31);
}

double vertexSpacingRadians() {
  return geo::degreesToRadians(terrain::vertexSpacingDegrees(kFineLevel, kN));
}

// The same scene in metres at any place. Level-20 tiles at 89.99° are 3.3 mm × 19 m slivers with
// 0.2 mm between columns (cos 89.99° = 1.7e-4), where east-west variation of integer heights
// could only be cliffs, so the heights vary north-south only: ridges along the parallels, vertex
// rows (counted from the place's reference row) at 0 or 1 m, hashed. Vertex spacing
// north-south is the same 1.19 m everywhere (1 % more at the pole: the meridian's curvature).
class RidgeScene {
 public:
  explicit RidgeScene(const Place& place) {
    const double spacing = terrain::vertexSpacingDegrees(kFineLevel, kN);
    referenceRow_ = static_cast<uint64_t>(std::floor((90.0 - place.latitudeDegrees) / spacing));
    referenceColumn_ =
        static_cast<uint64_t>(std::floor((place.longitudeDegrees + 180.0) / spacing));
    const double lon = terrain::vertexLongitudeDegrees(kFineLevel, kN, referenceColumn_);
    const double lat = terrain::vertexLatitudeDegrees(kFineLevel, kN, referenceRow_);
    referenceEcef_ = geo::cartographicToEcef(kWgs84, geo::Cartographic::fromDegrees(lon, lat, 0.0));
    frame_ = localFrame(lon, lat);
    columnMeters_ = vertexSpacingRadians() * std::hypot(referenceEcef_.x, referenceEcef_.y);
  }

  // Rows go in pairs: the mesh normals are central differences, which a 0, 1, 0, 1 pattern would
  // leave all vertical (and the hill-shading flat).
  int16_t height(uint64_t globalRow) const {
    const int64_t row = static_cast<int64_t>(globalRow) - static_cast<int64_t>(referenceRow_);
    const int64_t pair = (row < 0 ? row - 1 : row) / 2;  // floor(row / 2)
    return static_cast<int16_t>(mix(static_cast<uint64_t>(pair)) & 1);
  }

  // The tiles covering [westMeters, eastMeters] east-west and [-southMeters, northMeters]
  // north-south around the reference vertex; tile columns wrap at ±180°.
  std::vector<LoadedTile> tiles(double westMeters, double eastMeters, double southMeters,
                                double northMeters) const {
    const double rowMeters = vertexSpacingRadians() * kWgs84.semiMinorAxisMeters;  // < any row
    const auto rowsNorth = static_cast<uint64_t>(std::ceil(northMeters / rowMeters)) + 1;
    const auto rowsSouth = static_cast<uint64_t>(std::ceil(southMeters / rowMeters)) + 1;
    // Two tiles of margin: columns narrow towards the pole.
    const auto tileMeters = columnMeters_ * (kN - 1);
    const auto firstDx = static_cast<int64_t>(std::floor(westMeters / tileMeters)) - 2;
    const auto lastDx = static_cast<int64_t>(std::ceil(eastMeters / tileMeters)) + 2;
    const auto tilesX = static_cast<int64_t>(geo::GeographicTilingScheme::tilesX(kFineLevel));
    const auto centreX = static_cast<int64_t>(referenceColumn_ / (kN - 1));
    std::vector<LoadedTile> result;
    for (uint64_t y = (referenceRow_ - rowsNorth) / (kN - 1);
         y <= (referenceRow_ + rowsSouth) / (kN - 1); ++y) {
      for (int64_t dx = firstDx; dx <= lastDx; ++dx) {
        const auto x = static_cast<uint32_t>(((centreX + dx) % tilesX + tilesX) % tilesX);
        const geo::TileId id{kFineLevel, x, static_cast<uint32_t>(y)};
        const terrain::BlockGrid grid{id, kN};
        terrain::HeightBlock block{kN, std::vector<int16_t>(kN * kN)};
        for (uint32_t i = 0; i < kN; ++i) {
          std::fill_n(block.heights.begin() + i * kN, kN, height(grid.globalRow(i)));
        }
        result.push_back({id, std::move(block)});
      }
    }
    return result;
  }

  // A point given in the reference vertex's east/north/up frame.
  glm::dvec3 localToEcef(const glm::dvec3& eastNorthUpMeters) const {
    return referenceEcef_ + eastNorthUpMeters.x * frame_.east + eastNorthUpMeters.y * frame_.north +
           eastNorthUpMeters.z * frame_.up;
  }
  const LocalFrame& frame() const { return frame_; }

 private:
  uint64_t referenceRow_ = 0, referenceColumn_ = 0;
  glm::dvec3 referenceEcef_{0.0};
  LocalFrame frame_{};
  double columnMeters_ = 0.0;  // east-west vertex spacing on the reference row
};

// 1 m above the ridges (2 m above 0 m), 1 m west of the place, looking east 60° down along the
// ridges through a wide, low window: the ground from 0.4 to 1.6 m ahead (with the place, and the
// ±180° meridian 19.5 mm east of it, in the middle) and ±1.5 m across it, three ridges. Cheap at
// the pole, where every metre east-west costs 300 tiles, while north-south the view spans ridges.
constexpr int kViewWidth = 320, kViewHeight = 64;
constexpr double kFovXDegrees = 70.0, kPitchDegrees = -60.0;
const glm::dvec3 kEyeEastNorthUpMeters{-1.0, 0.0, 2.0};

// A 1 mm step must change the image (min > 0) and no step may change it much more than the others.
constexpr double kMaxStepOverMedian = 3.0;
// The same scene at the two places: the statistics agree within this factor.
constexpr double kPlaceRatio = 1.5;

struct StepStatistics {
  double min = 0, median = 0, max = 0, mean = 0;
  bool smooth() const { return min > 0.0 && max <= kMaxStepOverMedian * median; }
};

StepStatistics statisticsOf(std::vector<double> steps) {
  StepStatistics s;
  if (steps.empty()) return s;
  s.mean = std::accumulate(steps.begin(), steps.end(), 0.0) / static_cast<double>(steps.size());
  std::sort(steps.begin(), steps.end());
  s.min = steps.front();
  s.max = steps.back();
  s.median = steps[steps.size() / 2];
  return s;
}

std::ostream& operator<<(std::ostream& out, const StepStatistics& s) {
  return out << "1 mm steps min " << s.min << " median " << s.median << " max " << s.max << " mean "
             << s.mean;
}

class PlanetScalePrecision : public RenderTest {
 protected:
  void SetUp() override {
    RenderTest::SetUp();
    if (HasFatalFailure()) return;
    for (const auto& [scene, place] :
         {std::pair{&nearZero_, kNearZero}, std::pair{&pole_, kAntimeridianPole}}) {
      scene->place = place;
      scene->ridges = std::make_unique<RidgeScene>(place);
      // In view for every move below: 0.8 m west to 0.9 m east, ±2.2 m north-south.
      const auto tiles = scene->ridges->tiles(-0.8, 0.9, 2.2, 2.2);
      scene->ids = idsOf(tiles);
      upload(tiles);
    }
  }

  struct Scene {
    Place place{};
    std::unique_ptr<RidgeScene> ridges;
    std::vector<geo::TileId> ids;
  };

  // moveMeters in the reference frame (east, north, up); floatEye: the eye rounded to float, as a
  // renderer holding ECEF in float would have it.
  Image draw(const Scene& scene, const glm::dvec3& moveMeters, bool floatEye = false) {
    glm::dvec3 eye = scene.ridges->localToEcef(kEyeEastNorthUpMeters + moveMeters);
    if (floatEye) eye = roundedToFloat(eye);
    const LocalFrame& f = scene.ridges->frame();
    const double pitch = geo::degreesToRadians(kPitchDegrees);
    const glm::dvec3 forward = std::cos(pitch) * f.east + std::sin(pitch) * f.up;
    const double fovY = 2.0 * std::atan(std::tan(geo::degreesToRadians(kFovXDegrees) / 2.0) *
                                        kViewHeight / kViewWidth);
    const terrain::RenderView view =
        terrain::makeLookAtView(eye, eye + forward, f.up, fovY, kViewWidth, kViewHeight,
                                glm::normalize(f.up + 0.8 * f.north));
    return drawAndRead(view, scene.ids);
  }

  // Differences between consecutive images of the eye moved 0, 1, ..., count mm along axis.
  std::vector<double> millimetreSteps(const Scene& scene, const glm::dvec3& axis, int count,
                                      bool floatEye = false) {
    std::vector<double> steps;
    Image previous = draw(scene, glm::dvec3(0.0), floatEye);
    for (int k = 1; k <= count; ++k) {
      Image next = draw(scene, 0.001 * k * axis, floatEye);
      steps.push_back(meanAbsoluteDifference(previous, next));
      previous = std::move(next);
    }
    return steps;
  }

  Scene nearZero_, pole_;
};

const glm::dvec3 kEast{1, 0, 0}, kNorth{0, 1, 0}, kUp{0, 0, 1};

TEST_F(PlanetScalePrecision, MillimetreMovesAreSmoothAndAlikeAtTheAntimeridianPoleAndNearZero) {
  struct Axis {
    const char* name;
    glm::dvec3 direction;
  };
  for (const Axis& axis : {Axis{"north", kNorth}, Axis{"up", kUp}}) {
    StepStatistics statistics[2];
    double growth[2][3] = {};
    for (int p = 0; p < 2; ++p) {
      const Scene& scene = p == 0 ? nearZero_ : pole_;
      SCOPED_TRACE(std::string(scene.place.name) + " " + axis.name);
      statistics[p] = statisticsOf(millimetreSteps(scene, axis.direction, 12));
      EXPECT_TRUE(statistics[p].smooth()) << statistics[p];
      // Growing with the move, and a millimetre is small next to 20 cm.
      const Image base = draw(scene, glm::dvec3(0.0));
      const double moves[3] = {0.001, 0.05, 0.2};
      for (int m = 0; m < 3; ++m) {
        growth[p][m] = meanAbsoluteDifference(base, draw(scene, moves[m] * axis.direction));
        if (m > 0) {
          EXPECT_GT(growth[p][m], 2.0 * growth[p][m - 1]) << moves[m] << " m";
        }
      }
      std::cout << "[planet scale] " << scene.place.name << " " << axis.name << ": "
                << statistics[p] << "; vs start at 1 mm " << growth[p][0] << ", 5 cm "
                << growth[p][1] << ", 20 cm " << growth[p][2] << "\n";
    }
    SCOPED_TRACE(axis.name);
    EXPECT_LT(statistics[1].mean, kPlaceRatio * statistics[0].mean);
    EXPECT_GT(statistics[1].mean, statistics[0].mean / kPlaceRatio);
    for (int m = 1; m < 3; ++m) {
      EXPECT_LT(growth[1][m], kPlaceRatio * growth[0][m]);
      EXPECT_GT(growth[1][m], growth[0][m] / kPlaceRatio);
    }
  }
}

// Background pixels, for the failure message: a pinhole shows where a seam lets space through.
std::string holes(const Image& image) {
  std::string list;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (image.isBackground(x, y))
        list += " (" + std::to_string(x) + ", " + std::to_string(y) + ")";
    }
  }
  return list;
}

TEST_F(PlanetScalePrecision, TheViewIsFullDeterministicAndTheSameAtBothPlaces) {
  for (const Scene* scene : {&nearZero_, &pole_}) {
    SCOPED_TRACE(scene->place.name);
    const Image image = draw(*scene, glm::dvec3(0.0));
    savePng(image, std::string("planet_scale_") + scene->place.name);
    EXPECT_EQ(image.countNonBackground(), kViewWidth * kViewHeight) << "holes:" << holes(image);
    EXPECT_EQ(draw(*scene, glm::dvec3(0.0)).rgba, image.rgba);
    // Hill-shaded ridges, not one flat slope: the luminance spans a range.
    double lo = 255, hi = 0;
    for (int y = 0; y < image.height; ++y) {
      for (int x = 0; x < image.width; ++x) {
        lo = std::min(lo, image.luminance(x, y));
        hi = std::max(hi, image.luminance(x, y));
      }
    }
    EXPECT_GT(hi - lo, 25.0);
  }
  // The two places show the same scene, up to the meridian's curvature (1 % larger at the pole):
  // the images differ less than a 2 cm move changes one of them.
  const Image nearZero = draw(nearZero_, glm::dvec3(0.0));
  const double places = meanAbsoluteDifference(nearZero, draw(pole_, glm::dvec3(0.0)));
  const double twoCentimetres = meanAbsoluteDifference(nearZero, draw(nearZero_, 0.02 * kNorth));
  std::cout << "[planet scale] near_0_0 vs antimeridian_pole image difference " << places
            << ", a 2 cm move north " << twoCentimetres << "\n";
  EXPECT_LT(places, twoCentimetres);
}

// The scene is the same all along a parallel, so moving east must change nothing: while the tile
// seam at ±180° crosses the view, and when the eye itself crosses it (1.02 m east of the start).
// Over 1 m the parallel (1.1 km radius) turns by 0.9 mrad under the eye, which shifts the ridges in
// view by up to 1.4 mm: that move may change as much as a 2 mm move north, the others a tenth of 1
// mm.
TEST_F(PlanetScalePrecision, MovingEastAcrossTheAntimeridianChangesNothing) {
  const auto tiles = pole_.ridges->tiles(-0.8, 2.9, 2.2, 2.2);  // for the 1.03 m move too
  upload(tiles);
  pole_.ids = idsOf(tiles);
  const Image base = draw(pole_, glm::dvec3(0.0));
  const double north1mm = meanAbsoluteDifference(base, draw(pole_, 0.001 * kNorth));
  const double north2mm = meanAbsoluteDifference(base, draw(pole_, 0.002 * kNorth));
  ASSERT_GT(north1mm, 0.0);
  for (const double move : {0.005, 0.015, 0.05, 1.03}) {
    const Image moved = draw(pole_, move * kEast);
    EXPECT_EQ(moved.countNonBackground(), kViewWidth * kViewHeight)
        << move << " m, holes:" << holes(moved);
    const double difference = meanAbsoluteDifference(base, moved);
    std::cout << "[planet scale] antimeridian_pole east " << move << " m: " << difference
              << " (north 1 mm " << north1mm << ", 2 mm " << north2mm << ")\n";
    EXPECT_LT(difference, move < 1.0 ? north1mm / 10.0 : north2mm) << move << " m";
  }
}

// Rounding the eye to float (what a float-ECEF renderer would do; up is the ECEF x axis near
// (0, 0) and z at the pole, 6.4e6 m, multiples of 0.5 m in float) fails the smoothness check:
// millimetre moves up are lost.
TEST_F(PlanetScalePrecision, AFloatEcefEyeFailsTheSmoothnessCheck) {
  for (const Scene* scene : {&nearZero_, &pole_}) {
    const StepStatistics statistics = statisticsOf(millimetreSteps(*scene, kUp, 8, true));
    std::cout << "[planet scale] " << scene->place.name << " up, float eye: " << statistics << "\n";
    EXPECT_FALSE(statistics.smooth()) << scene->place.name << ": " << statistics;
  }
}

}  // namespace
}  // namespace globe::render::test
