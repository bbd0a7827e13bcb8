// Logarithmic depth from 0.5 m to 40,000 km: two planes facing the camera 0.1 % of their distance
// apart, drawn by the terrain renderer through its per-fragment and its per-vertex depth (and one
// of each), the farther one first: the nearer one must win wherever they overlap. And a camera
// 0.5 m above the ground sees no hole cut by the near plane.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include <glm/geometric.hpp>

#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "terrain/block_grid.hpp"
#include "terrain/tile_mesh.hpp"
#include "tests/render/render_test_support.hpp"
#include "tests/support/test_constants.hpp"

namespace globe::render::test {
namespace {

constexpr int kDepthViewWidth = 160, kDepthViewHeight = 120;
constexpr double kFovYDegrees = 20.0;  // the view is ±0.235 × ±0.176 of the distance
constexpr double kSeparation = 1e-3;   // the back plane is this fraction of D behind the front
using globe::test::kN;

// A rectangle facing the camera at distance D (along the view axis), in units of D on the camera's
// right and up axes.
struct PlaneShape {
  double centreRight, centreUp, halfWidth, halfHeight;
};

// Shapes chosen far (≥ 1.2×) from the renderer's rule (terrain_renderer.hpp): a tile is drawn with
// per-vertex depth when its nearest point is ≥ 1 km and ≥ 2 bounding radii away.
// Per fragment: radius ≥ 0.42 D, nearest ≤ 0.59 D. The front covers the left half of the view.
constexpr PlaneShape kNearFront{-0.12, 0.0, 0.12, 0.4};
constexpr PlaneShape kNearBack{0.0, 0.0, 0.4, 0.4};
// Per vertex: radius ≤ 0.25 D, nearest ≥ 0.75 D. The front covers the middle of the view.
constexpr PlaneShape kFarFront{0.0, 0.0, 0.07, 0.07};
constexpr PlaneShape kFarBack{0.0, 0.0, 0.2, 0.15};

struct Camera {
  glm::dvec3 eye, forward, right, up;
};

// 1 km above Mount Fuji's latitude and longitude (all three ECEF components are millions of
// metres), looking north-east and a little up, into space.
Camera makeCamera() {
  const LocalFrame f = localFrame(138.69, 35.30);
  Camera c;
  c.eye = geo::cartographicToEcef(kWgs84, geo::Cartographic::fromDegrees(138.69, 35.30, 1000.0));
  c.forward = glm::normalize(f.north + f.east + 0.3 * f.up);
  c.right = glm::normalize(glm::cross(c.forward, f.up));
  c.up = glm::cross(c.right, c.forward);
  return c;
}

glm::dvec3 planePoint(const Camera& c, double distance, double right, double up) {
  return c.eye + distance * (c.forward + right * c.right + up * c.up);
}

// A flat N×N grid over the rectangle, as a tile mesh: offsets from its centre, normals (and coarse
// normals) towards the camera, land (green) or sea (blue). Skirt vertices repeat their edge vertex:
// no area.
terrain::TileMesh planeMesh(const Camera& c, double distance, const PlaneShape& s, bool sea) {
  terrain::TileMesh mesh;
  mesh.verticesPerSide = kN;
  mesh.hasSkirts = true;
  mesh.centerEcefMeters = planePoint(c, distance, s.centreRight, s.centreUp);
  std::vector<glm::dvec3> grid;
  for (uint32_t i = 0; i < kN; ++i) {  // rows top to bottom, columns left to right: CCW faces us
    for (uint32_t j = 0; j < kN; ++j) {
      const double u = 2.0 * j / (kN - 1) - 1.0, v = 1.0 - 2.0 * i / (kN - 1);
      grid.push_back(
          planePoint(c, distance, s.centreRight + u * s.halfWidth, s.centreUp + v * s.halfHeight));
    }
  }
  std::vector<glm::dvec3> positions = grid;
  for (uint32_t edge = 0; edge < 4; ++edge) {
    for (uint32_t k = 0; k < kN; ++k) {
      const uint32_t row = edge == 0 ? 0 : edge == 1 ? kN - 1 : k;
      const uint32_t column = edge == 2 ? 0 : edge == 3 ? kN - 1 : k;
      positions.push_back(grid[terrain::gridVertexIndex(row, column, kN)]);
    }
  }
  for (const glm::dvec3& p : positions) {
    const glm::dvec3 offset = p - mesh.centerEcefMeters;
    mesh.vertices.insert(mesh.vertices.end(),
                         {static_cast<float>(offset.x), static_cast<float>(offset.y),
                          static_cast<float>(offset.z), static_cast<float>(-c.forward.x),
                          static_cast<float>(-c.forward.y), static_cast<float>(-c.forward.z), 0.0f,
                          sea ? 1.0f : 0.0f, 0.0f, 0.0f, static_cast<float>(-c.forward.x),
                          static_cast<float>(-c.forward.y), static_cast<float>(-c.forward.z)});
  }
  return mesh;
}

struct Overlap {
  int front = 0, frontWrong = 0;        // pixels well inside the front plane; not front-coloured
  int backOnly = 0, backOnlyWrong = 0;  // well inside the back plane only; not back-coloured
};

class PlanetScaleDepth : public RenderTest {
 protected:
  const geo::TileId frontId_{20, 100, 100}, backId_{20, 300, 300};  // not neighbours

  Overlap drawPlanes(double distance, const PlaneShape& front, const PlaneShape& back,
                     const std::string& pngName = "") {
    const Camera c = makeCamera();
    for (const auto& [id, shape, sea, d] :
         {std::tuple{frontId_, front, false, distance},
          std::tuple{backId_, back, true, distance * (1.0 + kSeparation)}}) {
      auto uploaded = renderer_->uploadTile(id, planeMesh(c, d, shape, sea));
      EXPECT_TRUE(uploaded.ok()) << uploaded.error();
    }
    const terrain::RenderView view =
        terrain::makeLookAtView(c.eye, c.eye + c.forward, c.up, geo::degreesToRadians(kFovYDegrees),
                                kDepthViewWidth, kDepthViewHeight, -c.forward);
    const std::vector<geo::TileId> ids{frontId_, backId_};
    FrameStats stats;
    const Image image = drawAndRead(view, ids, &stats);
    EXPECT_EQ(stats.tilesDrawn, 2u);
    if (!pngName.empty()) savePng(image, pngName);

    // Pixel rectangles of the planes (they face the camera: axis-aligned on screen).
    auto bounds = [&](const PlaneShape& s, double d) {
      const auto a = projectToPixel(
          view, planePoint(c, d, s.centreRight - s.halfWidth, s.centreUp + s.halfHeight));
      const auto b = projectToPixel(
          view, planePoint(c, d, s.centreRight + s.halfWidth, s.centreUp - s.halfHeight));
      EXPECT_TRUE(a && b);
      return std::array<double, 4>{a ? a->x : 0, a ? a->y : 0, b ? b->x : 0, b ? b->y : 0};
    };
    const auto f = bounds(front, distance);
    const auto k = bounds(back, distance * (1.0 + kSeparation));
    auto inside = [](const std::array<double, 4>& r, double x, double y, double margin) {
      return x > r[0] + margin && x < r[2] - margin && y > r[1] + margin && y < r[3] - margin;
    };
    Overlap overlap;
    for (int y = 0; y < kDepthViewHeight; ++y) {
      for (int x = 0; x < kDepthViewWidth; ++x) {
        const double cx = x + 0.5, cy = y + 0.5;
        const auto p = image.at(x, y);
        const bool green = p[1] > p[2], blue = p[2] > p[1];
        if (inside(f, cx, cy, 1.0)) {
          ++overlap.front;
          if (!green) ++overlap.frontWrong;
        } else if (!inside(f, cx, cy, -1.0) && inside(k, cx, cy, 1.0)) {
          ++overlap.backOnly;
          if (!blue) ++overlap.backOnlyWrong;
        }
      }
    }
    return overlap;
  }

  void expectNearerWins(double distance, const PlaneShape& front, const PlaneShape& back,
                        const char* path) {
    const Overlap o = drawPlanes(distance, front, back);
    SCOPED_TRACE(std::string(path) + " at " + std::to_string(distance) + " m");
    EXPECT_EQ(o.frontWrong, 0) << "of " << o.front << " pixels of the nearer plane";
    EXPECT_EQ(o.backOnlyWrong, 0) << "of " << o.backOnly << " pixels of the farther plane";
    // Both planes are in the picture: the check above is about something.
    EXPECT_GT(o.front, kDepthViewWidth * kDepthViewHeight / 20);
    EXPECT_GT(o.backOnly, kDepthViewWidth * kDepthViewHeight / 20);
  }
};

const double kAllDistances[] = {0.5, 1.0, 10.0, 100.0, 1e3, 1e4, 1e5, 1e6, 1e7, 4e7};
const double kFarDistances[] = {2e3, 1e4, 1e5, 1e6, 1e7, 4e7};

TEST_F(PlanetScaleDepth, PerFragmentDepthOrdersPlanesAPerMilleApart) {
  for (const double d : kAllDistances) expectNearerWins(d, kNearFront, kNearBack, "per fragment");
  drawPlanes(4e7, kNearFront, kNearBack, "depth_per_fragment_40000km");
}

TEST_F(PlanetScaleDepth, PerVertexDepthOrdersPlanesAPerMilleApart) {
  for (const double d : kFarDistances) expectNearerWins(d, kFarFront, kFarBack, "per vertex");
  drawPlanes(4e7, kFarFront, kFarBack, "depth_per_vertex_40000km");
}

// The two depth paths agree: a per-vertex plane in front of a per-fragment one, and the reverse.
TEST_F(PlanetScaleDepth, PerVertexAndPerFragmentDepthAgree) {
  for (const double d : kFarDistances) {
    expectNearerWins(d, kFarFront, kNearBack, "per-vertex front, per-fragment back");
    expectNearerWins(d, kNearFront, kFarBack, "per-fragment front, per-vertex back");
  }
}

// A camera 0.5 m above flat ground, looking down 50° with a 90° field of view: the ground in view
// is ≥ 0.26 m along the view axis, the near plane at 5 cm, so every pixel must be ground.
TEST_F(PlanetScaleDepth, HalfAMetreAboveTheGroundNothingIsClipped) {
  const auto centre = geo::GeographicTilingScheme::positionToTile(geo::degreesToRadians(138.69),
                                                                  geo::degreesToRadians(35.30), 20);
  ASSERT_TRUE(centre.has_value());
  std::vector<LoadedTile> tiles;
  for (uint32_t dy = 0; dy < 3; ++dy) {
    for (uint32_t dx = 0; dx < 3; ++dx) {
      tiles.push_back({geo::TileId{20, centre->x + dx - 1, centre->y + dy - 1},
                       terrain::HeightBlock{kN, std::vector<int16_t>(kN * kN, 100)}});
    }
  }
  upload(tiles);
  const terrain::BlockGrid grid{*centre, kN};
  const double lon = grid.longitudeDegrees(8), lat = grid.latitudeDegrees(8);
  const LocalFrame f = localFrame(lon, lat);
  const glm::dvec3 eye =
      geo::cartographicToEcef(kWgs84, geo::Cartographic::fromDegrees(lon, lat, 100.5));
  const double pitch = geo::degreesToRadians(-50.0);
  const glm::dvec3 forward = std::cos(pitch) * f.north + std::sin(pitch) * f.up;
  const terrain::RenderView view =
      terrain::makeLookAtView(eye, eye + forward, f.up, geo::degreesToRadians(90.0),
                              kDepthViewWidth, kDepthViewHeight, f.up);
  const Image image = drawAndRead(view, idsOf(tiles));
  savePng(image, "depth_half_metre_above_ground");
  EXPECT_EQ(image.countNonBackground(), kDepthViewWidth * kDepthViewHeight);
}

}  // namespace
}  // namespace globe::render::test
