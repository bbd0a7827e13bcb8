// A tileset streamed for a moving camera: CesiumGS's dragon (three levels by REPLACE, the finest
// file missing on purpose) refined as the camera comes near, the coarser level drawn while the
// finer loads and where it failed, dropped again as the camera leaves, culled behind it, and
// the surface collision reads following what is drawn.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "geo/ecef.hpp"
#include "tests/support/inline_runner.hpp"
#include "tests/tiles3d/box_tileset.hpp"
#include "tiles3d/drawn_surface.hpp"
#include "tiles3d/loaded_content.hpp"
#include "tiles3d/tileset.hpp"
#include "tiles3d/tileset_stream.hpp"

namespace globe::tiles3d::stream_test {
namespace {

namespace fs = std::filesystem;
const fs::path kDragon =
    fs::path(GLOBE_SOURCE_DIR) / "tests/data/interop/3dtiles/TilesetWithDiscreteLOD";
const geo::Ellipsoid kWgs84 = geo::Ellipsoid::wgs84();
constexpr double kDegree = 3.14159265358979323846 / 180;
// The dragon's box centre (its root transform's translation).
const glm::dvec3 kDragonEcef(1215107.7612304366, -4736682.902037748, 4081926.095098698);

// A 1000 × 1000 pixel view with a 60° field from `eye` towards `target`.
TileSelectionView viewFrom(const glm::dvec3& eye, const glm::dvec3& target) {
  // Any up not along the view direction.
  const glm::dvec3 direction = glm::normalize(target - eye);
  const glm::dvec3 side = glm::cross(
      direction, std::abs(direction.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0));
  const glm::dvec3 up = glm::normalize(glm::cross(side, direction));
  const glm::dmat4 view = glm::lookAt(eye, target, up);
  const glm::dmat4 projection = glm::perspective(60 * kDegree, 1.0, 1.0, 1e7);
  TileSelectionView v;
  v.cameraEcefMeters = eye;
  v.frustum = geo::Frustum::fromViewProjection(projection * view);
  v.pixelsPerRadian = 1000 / (2 * std::tan(30 * kDegree));
  return v;
}

// Frames until the view is complete, loads run between them; the frames' warnings gathered.
StreamFrame settle(TilesetStream& stream, globe::testing::InlineRunner& runner,
                   const TileSelectionView& view, std::vector<std::string>& warnings) {
  StreamFrame frame;
  for (int i = 0; i < 10; ++i) {
    frame = stream.update(view);
    warnings.insert(warnings.end(), frame.warnings.begin(), frame.warnings.end());
    if (frame.complete && runner.queued() == 0) break;
    runner.runAll();
  }
  return frame;
}

size_t trianglesDrawn(const TilesetStream& stream) {
  size_t n = 0;
  for (const DrawnItem& item : stream.drawn()) n += item.content->triangleCount;
  return n;
}

struct DragonStream : ::testing::Test {
  void SetUp() override {
    auto read = readTileset(kDragon);
    ASSERT_TRUE(read) << read.error();
    tileset = std::make_shared<const Tileset>(std::move(*read));
  }
  std::shared_ptr<const Tileset> tileset;
  globe::testing::InlineRunner runner;
  std::vector<std::string> warnings;
  // 20 km up from the dragon (its low level's 1 m error scaled 100× by its transform: 100 m,
  // 4.6 px from there), and inside its bounding sphere (925 m), looking at it.
  const glm::dvec3 far = kDragonEcef + 20000.0 * glm::normalize(kDragonEcef);
  const glm::dvec3 near = kDragonEcef + 600.0 * glm::normalize(glm::cross(kDragonEcef, {0, 0, 1}));
};

TEST_F(DragonStream, RefinesAsTheCameraComesNearAndCarriesOnWithoutTheMissingLevel) {
  TilesetStream stream(tileset, kWgs84, runner);
  const StreamFrame first = stream.update(viewFrom(far, kDragonEcef));
  EXPECT_EQ(first.wanted, 1u);  // the root's low dragon, nothing drawn before it arrives
  EXPECT_TRUE(stream.drawn().empty());
  EXPECT_FALSE(first.complete);
  settle(stream, runner, viewFrom(far, kDragonEcef), warnings);
  ASSERT_EQ(stream.drawn().size(), 1u);
  const size_t low = trianglesDrawn(stream);
  EXPECT_GT(low, 0u);

  // Near: the medium dragon is wanted; the low one stays drawn until it is in.
  const StreamFrame coming = stream.update(viewFrom(near, kDragonEcef));
  EXPECT_EQ(coming.wanted, 1u);
  EXPECT_EQ(trianglesDrawn(stream), low);
  const StreamFrame settled = settle(stream, runner, viewFrom(near, kDragonEcef), warnings);
  EXPECT_TRUE(settled.complete);
  const size_t medium = trianglesDrawn(stream);
  EXPECT_GT(medium, 2 * low);
  // The high dragon's file is missing: said once, by name, and the medium one drawn instead.
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("dragon_high.b3dm"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("drawn coarser"), std::string::npos) << warnings[0];
  const auto roof = stream.surface()->heightAt(-75.6121 * kDegree, 40.0427 * kDegree);
  ASSERT_TRUE(roof.has_value());
  EXPECT_GT(*roof, 300.0);
}

TEST_F(DragonStream, DropsTheFinerLevelAsTheCameraLeavesAndEvictsItOverBudget) {
  TilesetStream stream(tileset, kWgs84, runner, /*budgetBytes=*/1);
  settle(stream, runner, viewFrom(near, kDragonEcef), warnings);
  const size_t medium = trianglesDrawn(stream);
  const size_t mediumBytes = stream.residentBytes();
  // Leaving: the root's low dragon is wanted again (evicted over the 1-byte budget once the
  // medium one stood in for it); nothing stands in meanwhile; then the medium one is dropped.
  const StreamFrame leaving = stream.update(viewFrom(far, kDragonEcef));
  EXPECT_EQ(trianglesDrawn(stream), 0u);  // the root is not resident: nothing stands in
  EXPECT_EQ(leaving.wanted, 1u);
  const StreamFrame gone = settle(stream, runner, viewFrom(far, kDragonEcef), warnings);
  EXPECT_TRUE(gone.complete);
  EXPECT_LT(trianglesDrawn(stream), medium / 2);
  EXPECT_LT(stream.residentBytes(), mediumBytes);  // the medium dragon evicted
  EXPECT_EQ(stream.drawn().size(), 1u);
}

TEST_F(DragonStream, NothingBehindTheCameraIsDrawnOrLoadedButWhatIsBesideIt) {
  TilesetStream stream(tileset, kWgs84, runner);
  // 20 km up, looking straight up: the dragon is behind and far.
  const StreamFrame away = stream.update(viewFrom(far, far * 2.0));
  EXPECT_TRUE(away.complete);
  EXPECT_EQ(away.wanted, 0u);
  EXPECT_TRUE(stream.drawn().empty());
  EXPECT_FALSE(stream.surface()->heightAt(-75.6121 * kDegree, 40.0427 * kDegree).has_value());
  // Inside the dragon's box, looking away from it: within reach of the camera, still wanted.
  const glm::dvec3 inside = kDragonEcef + 100.0 * glm::normalize(kDragonEcef);
  const StreamFrame beside = stream.update(viewFrom(inside, inside * 2.0));
  EXPECT_GT(beside.wanted, 0u);
}

std::shared_ptr<const LoadedContent> boxAt(double lonDeg, double latDeg, double heightMeters) {
  auto content = loadContent(testing::boxGlb(10, 10, heightMeters),
                             testing::eastNorthUp(lonDeg, latDeg, 0), kWgs84, "box");
  EXPECT_TRUE(content) << content.error();
  return std::make_shared<const LoadedContent>(std::move(*content));
}

// The surface collision reads from what a frame draws: each box's roof on it, the higher where
// two overlap, nothing between; boxes either side of ±180° and near a pole each found.
TEST(DrawnSurface, ReadsEachDrawnRoofAcrossTheAntimeridianAndNearThePole) {
  const DrawnSurface surface({boxAt(179.9999, 10, 30), boxAt(-179.9999, 10, 40),
                              boxAt(179.9999, 10, 25), boxAt(20, 89.99, 50)});
  const auto at = [&](double lonDeg, double latDeg) {
    return surface.heightAt(lonDeg * kDegree, latDeg * kDegree);
  };
  ASSERT_TRUE(at(179.9999, 10).has_value());
  EXPECT_NEAR(*at(179.9999, 10), 30.0, 0.5);  // the higher of the two boxes there
  ASSERT_TRUE(at(-179.9999, 10).has_value());
  EXPECT_NEAR(*at(-179.9999, 10), 40.0, 0.5);
  EXPECT_FALSE(at(180.0, 10).has_value());  // between them: 11 m of open ground
  EXPECT_FALSE(at(0, 10).has_value());
  ASSERT_TRUE(at(20, 89.99).has_value());
  EXPECT_NEAR(*at(20, 89.99), 50.0, 0.5);
  EXPECT_NEAR(surface.maximumHeightMeters(), 50.0, 1e-3);
  EXPECT_FALSE(DrawnSurface().heightAt(0, 0).has_value());
}

}  // namespace
}  // namespace globe::tiles3d::stream_test
