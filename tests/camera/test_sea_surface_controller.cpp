// The camera over water, on blocks loaded through the tile store as the viewer loads them: by
// default the water surface at 0 m is the ground (a camera diving into the sea stops at its eye
// clearance above it); with the sea floor (--sea-floor) it goes under water down to the floor.
// Land below sea level is land in both. The controller's ground is the drawn mesh's.
#include <gtest/gtest.h>
#include <unistd.h>

#include <deque>
#include <filesystem>
#include <ostream>
#include <string>

#include <glm/geometric.hpp>

#include "camera/camera_controller.hpp"
#include "collision/collision_response.hpp"
#include "collision/exact_surface.hpp"
#include "geo/ecef.hpp"
#include "streaming/tile_store.hpp"
#include "terrain/tile_mesh.hpp"
#include "tests/support/sea_test_pyramid.hpp"
#include "tests/support/test_constants.hpp"

namespace globe::terrain {
// How GoogleTest prints the parameter (CTest's test names include it), instead of its raw byte.
void PrintTo(SeaSurface surface, std::ostream* os);
void PrintTo(SeaSurface surface, std::ostream* os) {
  *os << (surface == SeaSurface::Water ? "Water" : "SeaFloor");
}
}  // namespace globe::terrain

namespace globe::camera {
namespace {

namespace fs = std::filesystem;
using globe::test::kDt;
using globe::test::kWgs84;
using terrain::SeaSurface;

// A place to dive into, and the ground there under either sea surface.
struct Spot {
  const char* name;
  geo::TileId tile;
  uint32_t row, column;  // the cell whose centre the camera dives at
  double waterSurfaceMeters;
  double seaFloorMeters;
};
const Spot kSpots[] = {
    {"open sea", globe::testing::kSeaTile, 7, 7, 0.0, globe::testing::kSeaFloorMeters},
    {"water over a known floor beside land", globe::testing::kMixedTile, 6, 1, 0.0,
     globe::testing::kSeaFloorMeters},
    {"water of unknown depth", globe::testing::kMixedTile, 6, 5, 0.0, 0.0},
    {"land below sea level", globe::testing::kMixedTile, 6, 9,
     globe::testing::kMixedLandBelowSeaLevelMeters, globe::testing::kMixedLandBelowSeaLevelMeters},
    {"land", globe::testing::kMixedTile, 6, 13, globe::testing::kMixedLandMeters,
     globe::testing::kMixedLandMeters},
};

class SeaSurfaceController : public ::testing::TestWithParam<SeaSurface> {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("globe_sea_controller_" + std::to_string(::getpid()) + "_" +
                                        std::to_string(static_cast<int>(GetParam())));
    fs::remove_all(dir_);
    ASSERT_TRUE(globe::testing::writeSeaTestPyramid(dir_));
    // The blocks as the viewer gets them: from a store opened with the view's sea surface.
    auto store = streaming::TileStore::open(dir_, GetParam());
    ASSERT_TRUE(store) << store.error();
    std::vector<terrain::ArrayTile> tiles;
    for (uint32_t dy = 0; dy < 2; ++dy) {
      for (uint32_t dx = 0; dx < 2; ++dx) {
        const geo::TileId id{globe::testing::kSeaTestLevel, globe::testing::kSeaTile.x + dx,
                             globe::testing::kSeaTile.y + dy};
        auto block = (*store)->loadBlock(id);
        ASSERT_TRUE(block) << block.error();
        blocks_.push_back(std::move(*block));
        tiles.push_back(terrain::makeArrayTile(id, blocks_.back()));
      }
    }
    array_.assign(std::move(tiles));
  }
  void TearDown() override { fs::remove_all(dir_); }

  double expectedGround(const Spot& spot) const {
    return GetParam() == SeaSurface::Water ? spot.waterSurfaceMeters : spot.seaFloorMeters;
  }
  static geo::Cartographic above(const Spot& spot, double heightMeters) {
    const auto centre = globe::testing::cellCentreDegrees(spot.tile, spot.row, spot.column);
    return geo::Cartographic::fromDegrees(centre.longitude, centre.latitude, heightMeters);
  }

  fs::path dir_;
  std::deque<terrain::HeightBlock> blocks_;  // stable addresses for the array's tiles
  terrain::RenderingTileArray array_;
};

TEST_P(SeaSurfaceController, TheDrawnMeshAndCollisionStandOnTheSameGround) {
  for (const Spot& spot : kSpots) {
    SCOPED_TRACE(spot.name);
    const geo::Cartographic at = above(spot, 0.0);
    const auto exact =
        collision::exactSurfaceHeight(array_, kWgs84, at.longitudeRadians, at.latitudeRadians);
    ASSERT_TRUE(exact);
    EXPECT_NEAR(exact->heightMeters, expectedGround(spot), 0.1);  // a cell's chord sags 6 cm
    // The mesh's vertex at the cell's north-west corner is at the block's surface height.
    const terrain::HeightBlock& block =
        *array_.lookupIndexed(at.longitudeRadians, at.latitudeRadians).tile->block;
    const terrain::TileMesh mesh = terrain::buildTileMesh(spot.tile, block, kWgs84, 0.0);
    const float* offset = &mesh.vertices[size_t{terrain::gridVertexIndex(spot.row, spot.column,
                                                                         block.verticesPerSide)} *
                                         terrain::kTileVertexFloats];
    const auto corner = geo::ecefToCartographic(
        kWgs84, mesh.centerEcefMeters + glm::dvec3(offset[0], offset[1], offset[2]));
    ASSERT_TRUE(corner);
    EXPECT_NEAR(corner->heightMeters, expectedGround(spot), 0.01);
  }
}

TEST_P(SeaSurfaceController, ACameraDivingStraightDownStopsAtTheGroundItsClearanceAbove) {
  const double clearance = ControllerSettings{}.clearance.eyeMeters;
  for (const Spot& spot : kSpots) {
    SCOPED_TRACE(spot.name);
    const double ground = expectedGround(spot);
    // By velocity: 90 m/s down for 10 s, from 300 m above the water surface.
    CameraController controller({above(spot, 300.0), 0.0, -1.5, 0.0});
    const glm::dvec3 down = -geo::geodeticSurfaceNormal(kWgs84, above(spot, 0.0));
    ASSERT_TRUE(controller.setVelocity(90.0 * down));
    double lowest = 1e9;
    for (int frame = 0; frame < 300; ++frame) {
      const CollisionState& state = controller.update(kDt, array_, kWgs84);
      lowest = std::min(lowest, controller.pose().position.heightMeters);
      ASSERT_TRUE(state.terrainFound);
      EXPECT_NEAR(state.terrainHeightMeters, ground, 0.1);
    }
    EXPECT_GE(lowest, ground + clearance - collision::kContactSkinMeters - 0.1);
    EXPECT_NEAR(controller.pose().position.heightMeters, ground + clearance, 0.1);

    // By proposed poses: 25 m lower each frame, far below the floor in the end.
    CameraController proposed({above(spot, 300.0), 0.0, -1.5, 0.0});
    lowest = 1e9;
    for (int frame = 1; frame <= 120; ++frame) {
      ASSERT_TRUE(proposed.propose({above(spot, 300.0 - 25.0 * frame), 0.0, -1.5, 0.0}));
      proposed.update(kDt, array_, kWgs84);
      lowest = std::min(lowest, proposed.pose().position.heightMeters);
    }
    EXPECT_GE(lowest, ground + clearance - collision::kContactSkinMeters - 0.1);
    EXPECT_NEAR(proposed.pose().position.heightMeters, ground + clearance, 0.1);
  }
}

TEST_P(SeaSurfaceController, OnlyTheSeaFloorLetsTheCameraUnderWater) {
  const Spot& sea = kSpots[0];
  CameraController controller({above(sea, 50.0), 0.0, -1.5, 0.0});
  for (int frame = 1; frame <= 60; ++frame) {
    ASSERT_TRUE(controller.propose({above(sea, 50.0 - 10.0 * frame), 0.0, -1.5, 0.0}));
    controller.update(kDt, array_, kWgs84);
  }
  const double height = controller.pose().position.heightMeters;
  if (GetParam() == SeaSurface::Water) {
    EXPECT_GT(height, 1.9) << "the water surface is the ground";
  } else {
    EXPECT_LT(height, -150.0) << "under water";
    EXPECT_GT(height, globe::testing::kSeaFloorMeters + 1.9) << "above the floor";
  }
}

INSTANTIATE_TEST_SUITE_P(Sea, SeaSurfaceController,
                         ::testing::Values(SeaSurface::Water, SeaSurface::SeaFloor),
                         [](const auto& param) {
                           return std::string(param.param == SeaSurface::Water ? "WaterSurface"
                                                                               : "SeaFloor");
                         });

}  // namespace
}  // namespace globe::camera
