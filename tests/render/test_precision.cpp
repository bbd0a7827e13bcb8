// Camera-relative precision at earth radius: on synthetic level-20 tiles (~1.2 m vertex spacing)
// with metre-sized bumps, a camera 1 m above them moves by millimetres to decimetres and the
// image follows smoothly, with no 0.5 m float steps (the float spacing of ECEF at 6,400 km).
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "terrain/block_grid.hpp"
#include "terrain/tile_mesh.hpp"
#include "tests/render/render_test_support.hpp"
#include "tests/support/test_constants.hpp"

namespace globe::render::test {
namespace {

constexpr uint32_t kLevel = 20;
using globe::test::kN;

// 100 m plus 0, 1 or 2 m, a hash of the global vertex: neighbouring tiles agree on edges.
int16_t bumpHeight(uint64_t globalRow, uint64_t globalColumn) {
  uint64_t h = globalRow * 0x9E3779B97F4A7C15ULL ^ (globalColumn + 0x632BE59BD9B4E019ULL);
  h ^= h >> 29;
  h *= 0xBF58476D1CE4E5B9ULL;
  h ^= h >> 32;
  return static_cast<int16_t>(100 + h % 3);
}

class Precision : public RenderTest {
 protected:
  void SetUp() override {
    RenderTest::SetUp();
    if (HasFatalFailure()) return;
    const auto centre = geo::GeographicTilingScheme::positionToTile(
        geo::degreesToRadians(138.69), geo::degreesToRadians(35.30), kLevel);
    ASSERT_TRUE(centre.has_value());
    centre_ = *centre;
    std::vector<LoadedTile> tiles;
    for (uint32_t dy = 0; dy < 3; ++dy) {
      for (uint32_t dx = 0; dx < 3; ++dx) {
        const geo::TileId id{kLevel, centre_.x + dx - 1, centre_.y + dy - 1};
        const terrain::BlockGrid grid{id, kN};
        terrain::HeightBlock block{kN, std::vector<int16_t>(kN * kN)};
        for (uint32_t i = 0; i < kN; ++i) {
          for (uint32_t j = 0; j < kN; ++j) {
            block.heights[i * kN + j] = bumpHeight(grid.globalRow(i), grid.globalColumn(j));
          }
        }
        tiles.push_back({id, std::move(block)});
        ids_.push_back(id);
      }
    }
    upload(tiles);
  }

  // 1 m above the highest bump in the middle tile, looking north-east 50° down. floatEye: the eye
  // rounded to float, as a renderer holding ECEF in float would have it.
  terrain::RenderView view(double eastMeters, bool floatEye = false) const {
    const terrain::BlockGrid grid{centre_, kN};
    const double lon = grid.longitudeDegrees(8), lat = grid.latitudeDegrees(8);
    const LocalFrame frame = localFrame(lon, lat);
    glm::dvec3 eye =
        geo::cartographicToEcef(kWgs84, geo::Cartographic::fromDegrees(lon, lat, 103.0)) +
        eastMeters * frame.east;
    if (floatEye) eye = roundedToFloat(eye);
    const double pitch = geo::degreesToRadians(-50.0);
    const glm::dvec3 forward =
        std::cos(pitch) * glm::normalize(frame.north + frame.east) + std::sin(pitch) * frame.up;
    return terrain::makeLookAtView(eye, eye + forward, frame.up, geo::degreesToRadians(60.0),
                                   kWidth, kHeight, glm::normalize(frame.up + 0.8 * frame.east));
  }

  geo::TileId centre_{};
  std::vector<geo::TileId> ids_;
};

TEST_F(Precision, SmallCameraMovesChangeTheImageSmoothly) {
  const Image base = drawAndRead(view(0.0), ids_);
  savePng(base, "precision_level20_1m_above_bumps");
  EXPECT_EQ(base.countNonBackground(), kWidth * kHeight);
  EXPECT_EQ(drawAndRead(view(0.0), ids_).rgba, base.rgba);  // deterministic
  auto meanDifference = [&](double eastMeters) {
    const Image moved = drawAndRead(view(eastMeters), ids_);
    double sum = 0;
    for (size_t k = 0; k < base.rgba.size(); ++k) {
      sum += std::abs(static_cast<int>(base.rgba[k]) - static_cast<int>(moved.rgba[k]));
    }
    return sum / static_cast<double>(base.rgba.size());
  };
  // A float-ECEF renderer would show no change at all below ~25 cm, then a jump.
  const double millimetre = meanDifference(0.001);
  EXPECT_GT(millimetre, 0.0);
  EXPECT_LT(millimetre, 0.5);
  double previous = millimetre;
  for (const double move : {0.02, 0.05, 0.10, 0.20}) {
    const double difference = meanDifference(move);
    EXPECT_GT(difference, previous) << "move " << move << " m";
    previous = difference;
  }
  EXPECT_GT(previous, 2.0);

  // The check above can fail: with the eye in float (ECEF components of 3.4e6-3.9e6 m are
  // multiples of 0.25 m there), the same millimetre move does not change the image at all.
  const Image floatBase = drawAndRead(view(0.0, true), ids_);
  EXPECT_EQ(meanAbsoluteDifference(floatBase, drawAndRead(view(0.001, true), ids_)), 0.0);
}

}  // namespace
}  // namespace globe::render::test
