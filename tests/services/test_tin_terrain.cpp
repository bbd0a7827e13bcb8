// A quantized-mesh tree's TIN tiles drawn and collided as TINs: the bundled pyramid around Mount
// Fuji exported as a simplified Cesium terrain tree (publish/quantized_mesh_export.hpp), read back
// through the quantized-mesh source. Each tile's mesh has the file's own vertices (not a resampled
// grid); QOTCD on them is the paper's rule (the highest vertex of the triangle under the point) and
// never below the drawn surface; camera flights into the summit keep the eye and the near plane
// above it every frame. The drawn surface is found here by brute force over every triangle of the
// tile, in ECEF, apart from the collision code's cell grid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "camera/camera_controller.hpp"
#include "camera/camera_motion.hpp"
#include "collision/qotcd_height.hpp"
#include "formats/quantized_mesh.hpp"
#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "publish/quantized_mesh_export.hpp"
#include "services/terrain_services.hpp"
#include "streaming/tile_store.hpp"
#include "terrain/rendering_tile_array.hpp"
#include "terrain/tile_mesh.hpp"
#include "terrain/tin_tile.hpp"
#include "tests/support/quantized_mesh_file.hpp"
#include "tests/support/test_constants.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::services {
namespace {

namespace fs = std::filesystem;
using globe::test::kWgs84;
using Scheme = geo::GeographicTilingScheme;

// Around Kengamine, Fuji's summit: the exported region, and its finest level (the pyramid's).
constexpr double kWest = 138.69, kSouth = 35.33, kEast = 138.77, kNorth = 35.39;
constexpr double kSummitLon = 138.7275, kSummitLat = 35.3606;

struct Tree {
  fs::path dir;
  std::unique_ptr<streaming::TerrainSource> source;
  std::vector<terrain::HeightBlock> blocks;  // of `tiles`, kept for the array
  uint32_t level = 0;                        // the tree's finest
  std::vector<geo::TileId> tiles;            // of that level over the region
  terrain::RenderingTileArray array;
};

fs::path exportTree(double errorFraction, const std::string& name) {
  const fs::path dir = globe::testing::freshTempDir(name);
  auto pyramid = streaming::TileStore::open(globe::testing::bundledPyramid());
  EXPECT_TRUE(pyramid) << pyramid.error();
  publish::ExportRegion region{0, UINT32_MAX, kWest, kSouth, kEast, kNorth};
  auto report = publish::exportQuantizedMesh(**pyramid, region, dir, kWgs84, errorFraction);
  EXPECT_TRUE(report) << report.error();
  return dir;
}

// The tree's finest tiles over the region, loaded through the quantized-mesh source.
std::unique_ptr<Tree> openTree(double errorFraction, const std::string& name) {
  auto tree = std::make_unique<Tree>();
  tree->dir = exportTree(errorFraction, name);
  transport::NetworkSettings settings;
  settings.useCache = false;
  auto source =
      openTerrainSource("quantized-mesh:" + tree->dir.string(), terrain::SeaSurface::Water,
                        std::make_shared<transport::Network>(settings));
  EXPECT_TRUE(source) << source.error();
  tree->source = std::move(*source);
  const uint32_t level = tree->level = tree->source->manifest().maxLevel();
  const double size = 180.0 / static_cast<double>(1u << level);
  for (auto x = static_cast<uint32_t>((kWest + 180) / size); x * size - 180 < kEast; ++x) {
    for (auto y = static_cast<uint32_t>((90 - kNorth) / size); 90 - y * size > kSouth; ++y) {
      auto block = tree->source->loadBlock({level, x, y});
      EXPECT_TRUE(block) << block.error();
      tree->tiles.push_back({level, x, y});
      tree->blocks.push_back(std::move(*block));
    }
  }
  std::vector<terrain::ArrayTile> tiles;
  for (size_t k = 0; k < tree->tiles.size(); ++k) {
    tiles.push_back(terrain::makeArrayTile(tree->tiles[k], tree->blocks[k]));
  }
  tree->array.assign(std::move(tiles));
  return tree;
}

const Tree& simplified() {
  static const std::unique_ptr<Tree> tree = openTree(1.0, "tin-terrain-simplified");
  return *tree;
}

formats::QuantizedMesh decodeFile(const fs::path& path) {
  auto mesh = globe::testing::readQuantizedMeshFile(path);
  EXPECT_TRUE(mesh) << mesh.error();
  return mesh ? std::move(*mesh) : formats::QuantizedMesh{};
}

fs::path tileFile(const fs::path& dir, const geo::TileId& tile) {
  const uint32_t tmsY = Scheme::tilesY(tile.level) - 1 - tile.y;
  return dir / std::to_string(tile.level) / std::to_string(tile.x) /
         (std::to_string(tmsY) + ".terrain");
}

// A TIN vertex's ECEF position, from the tile's bounds (not TinTile's code).
glm::dvec3 vertexEcef(const terrain::TinTile& tin, uint32_t k) {
  const terrain::TinVertex& p = tin.vertices()[k];
  const geo::GlobeRectangle& r = tin.rectangle();
  return geo::cartographicToEcef(
      kWgs84, {r.westRadians + p.u * (r.eastRadians - r.westRadians),
               r.southRadians + p.v * (r.northRadians - r.southRadians), p.heightMeters});
}

// The drawn surface under (lon, lat), by brute force: the normal line through the ellipsoid
// point cut with every triangle of the tile holding it; where it passes between triangles (a
// sliver at an edge), the plane of the one it misses least.
double bruteForceDrawnHeight(const terrain::RenderingTileArray& array, double lon, double lat) {
  const terrain::ArrayTile* tile = array.findIndexed(lon, lat);
  if (tile == nullptr || !tile->block->tin) return NAN;
  const terrain::TinTile& tin = *tile->block->tin;
  const glm::dvec3 s = geo::cartographicToEcef(kWgs84, {lon, lat, 0.0});
  const glm::dvec3 n = geo::geodeticSurfaceNormal(kWgs84, geo::Cartographic{lon, lat, 0.0});
  double best = -INFINITY, bestHeight = NAN;
  for (size_t k = 0; k + 2 < tin.triangles().size(); k += 3) {
    const glm::dvec3 a = vertexEcef(tin, tin.triangles()[k]) - s;
    const glm::dvec3 b = vertexEcef(tin, tin.triangles()[k + 1]) - s;
    const glm::dvec3 c = vertexEcef(tin, tin.triangles()[k + 2]) - s;
    const glm::dvec3 normal = glm::cross(b - a, c - a);
    const double along = glm::dot(normal, n);
    if (std::abs(along) < 1e-9 * glm::length(normal)) continue;
    const double h = glm::dot(normal, a) / along;
    const glm::dvec3 x = h * n;
    const double area = glm::dot(normal, normal);
    const double wa = glm::dot(normal, glm::cross(b - x, c - x)) / area;
    const double wb = glm::dot(normal, glm::cross(c - x, a - x)) / area;
    const double worst = std::min({wa, wb, 1.0 - wa - wb});
    if (worst > best) best = worst, bestHeight = h;
  }
  return bestHeight;
}

// The paper's rule by brute force in (u, v): the highest vertex of a triangle holding the point.
double bruteForceRule(const terrain::TinTile& tin, double u, double v) {
  double highest = -INFINITY;
  const auto& p = tin.vertices();
  const auto& t = tin.triangles();
  for (size_t k = 0; k + 2 < t.size(); k += 3) {
    const auto &a = p[t[k]], &b = p[t[k + 1]], &c = p[t[k + 2]];
    const double area = (b.u - a.u) * (c.v - a.v) - (c.u - a.u) * (b.v - a.v);
    if (area == 0) continue;
    const double wa = ((b.u - u) * (c.v - v) - (c.u - u) * (b.v - v)) / area;
    const double wb = ((c.u - u) * (a.v - v) - (a.u - u) * (c.v - v)) / area;
    if (wa < -1e-9 || wb < -1e-9 || 1 - wa - wb < -1e-9) continue;
    double h = -INFINITY;
    if (wa > 1e-9) h = std::max(h, a.heightMeters);
    if (wb > 1e-9) h = std::max(h, b.heightMeters);
    if (1 - wa - wb > 1e-9) h = std::max(h, c.heightMeters);
    highest = std::max(highest, h);
  }
  return highest;
}

TEST(TinTerrain, EachTileIsDrawnWithItsOwnVerticesAndTriangles) {
  const Tree& tree = simplified();
  ASSERT_GE(tree.tiles.size(), 8u);
  std::printf("level %u: %zu tiles\n", tree.level, tree.tiles.size());
  size_t tinTriangles = 0;
  for (size_t k = 0; k < tree.tiles.size(); ++k) {
    const terrain::HeightBlock& block = tree.blocks[k];
    ASSERT_TRUE(block.tin) << geo::tileName(tree.tiles[k]);
    const formats::QuantizedMesh file = decodeFile(tileFile(tree.dir, tree.tiles[k]));
    EXPECT_EQ(block.tin->vertices().size(), file.vertexCount());
    EXPECT_EQ(block.tin->triangleCount(), file.triangles.size() / 3);
    const terrain::TileMesh mesh = terrain::buildTileMesh(tree.tiles[k], block, kWgs84, 100.0);
    size_t edgeVertices = 0;
    for (size_t v = 0; v < file.vertexCount(); ++v) {
      edgeVertices += (file.u[v] == 0) + (file.u[v] == formats::kQuantizedMax) + (file.v[v] == 0) +
                      (file.v[v] == formats::kQuantizedMax);
    }
    // The file's vertices and a skirt vertex under each edge vertex; its triangles and two per
    // edge segment (an edge of m vertices has m - 1).
    EXPECT_EQ(mesh.vertexCount(), file.vertexCount() + edgeVertices);
    EXPECT_EQ(mesh.indices.size() / 3, file.triangles.size() / 3 + 2 * (edgeVertices - 4));
    tinTriangles += file.triangles.size() / 3;
  }
  // Simplified to its geometric error, the tree draws far fewer triangles than the full grid.
  const size_t gridTriangles = tree.tiles.size() * 2 * 64 * 64;
  std::printf("TIN triangles %zu, full-grid %zu (%.3fx)\n", tinTriangles, gridTriangles,
              static_cast<double>(tinTriangles) / static_cast<double>(gridTriangles));
  EXPECT_LE(static_cast<double>(tinTriangles), 0.35 * static_cast<double>(gridTriangles));
}

TEST(TinTerrain, QotcdOnTinIsThePapersRuleAndNeverBelowTheDrawnSurface) {
  const Tree& tree = simplified();
  std::mt19937_64 rng(54);
  std::uniform_real_distribution<double> lon(geo::degreesToRadians(kWest + 0.001),
                                             geo::degreesToRadians(kEast - 0.001));
  std::uniform_real_distribution<double> lat(geo::degreesToRadians(kSouth + 0.001),
                                             geo::degreesToRadians(kNorth - 0.001));
  int triangleCases = 0;
  double worstBelow = 0;
  for (int k = 0; k < 3000; ++k) {
    const double x = lon(rng), y = lat(rng);
    const terrain::ArrayTile* tile = tree.array.findIndexed(x, y);
    ASSERT_NE(tile, nullptr);
    const collision::TileHeight h = collision::qotcdTileHeight(*tile, x, y);
    ASSERT_EQ(h.heightCase, collision::HeightCase::Triangle);
    ++triangleCases;
    const terrain::TinTile& tin = *tile->block->tin;
    const double u = (x - tile->westRadians) / (tile->eastRadians - tile->westRadians);
    const double v = (y - tile->southRadians) / (tile->northRadians - tile->southRadians);
    EXPECT_DOUBLE_EQ(h.heightMeters, bruteForceRule(tin, u, v)) << x << " " << y;
    const double drawn = bruteForceDrawnHeight(tree.array, x, y);
    worstBelow = std::min(worstBelow, h.heightMeters - drawn);
  }
  EXPECT_EQ(triangleCases, 3000);
  EXPECT_GE(worstBelow, 0.0);  // H is never below the drawn TIN
}

// How far the eye and the near-plane corners are above the brute-force drawn surface.
double lowestClearance(const camera::CameraPose& pose, const camera::NearPlane& nearPlane,
                       const terrain::RenderingTileArray& array) {
  const camera::CameraFrame frame = camera::cameraFrame(kWgs84, pose);
  double lowest =
      pose.position.heightMeters -
      bruteForceDrawnHeight(array, pose.position.longitudeRadians, pose.position.latitudeRadians);
  for (const glm::dvec3& offset : camera::nearPlaneCornerOffsets(frame, nearPlane)) {
    const auto p = geo::ecefToCartographic(kWgs84, frame.positionEcefMeters + offset);
    if (!p) return -INFINITY;
    lowest = std::min(lowest, p->heightMeters - bruteForceDrawnHeight(array, p->longitudeRadians,
                                                                      p->latitudeRadians));
  }
  return lowest;
}

TEST(TinTerrain, FlightsIntoTheSummitOverTinTerrainStayAboveItEveryFrame) {
  const Tree& tree = simplified();
  camera::ControllerSettings settings;
  int frames = 0, below = 0, collided = 0;
  double lowest = INFINITY;
  for (int b = 0; b < 8; ++b) {
    for (const double step : {1.0, 10.0, 60.0}) {
      for (const double pitchDegrees : {0.0, -25.0}) {
        const double bearing = b * std::numbers::pi / 4;
        // Start 2 km out at 3 m above the drawn ground (level) or 300 m (descending), heading in.
        const geo::Cartographic summit =
            geo::Cartographic::fromDegrees(kSummitLon, kSummitLat, 0.0);
        const glm::dvec3 centre = geo::cartographicToEcef(kWgs84, summit);
        const camera::EastNorthUp enu = camera::eastNorthUp(kWgs84, summit);
        geo::Cartographic start = *geo::ecefToCartographic(
            kWgs84,
            centre + 2000.0 * (std::sin(bearing) * enu.east + std::cos(bearing) * enu.north));
        start.heightMeters =
            bruteForceDrawnHeight(tree.array, start.longitudeRadians, start.latitudeRadians) +
            (pitchDegrees == 0.0 ? 3.0 : 300.0);
        const double heading = bearing + std::numbers::pi;
        const double pitch = geo::degreesToRadians(pitchDegrees);
        camera::CameraController controller({start, heading, pitch, 0.0}, settings);
        const glm::dvec3 forward =
            camera::cameraFrame(kWgs84, {start, heading, pitch, 0.0}).forward;
        ASSERT_TRUE(controller.setVelocity(forward * (step / globe::test::kDt)));
        for (int frame = 0; frame < 60; ++frame) {
          const camera::CollisionState& state =
              controller.update(globe::test::kDt, tree.array, kWgs84);
          const double clearance =
              lowestClearance(controller.pose(), settings.nearPlane, tree.array);
          ++frames;
          below += !(clearance >= 0.0);
          collided += state.collided;
          lowest = std::min(lowest, clearance);
        }
      }
    }
  }
  std::printf("%d frames over TIN terrain, %d collided, %d below, lowest clearance %.3f m\n",
              frames, collided, below, lowest);
  EXPECT_GT(collided, 100);  // the flights did meet the mountain
  EXPECT_EQ(below, 0);
}

}  // namespace
}  // namespace globe::services
