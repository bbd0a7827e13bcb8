// The pieces of globe_buildings on shapes whose answers are known: heights from attributes,
// roofs with holes (area covered, winding), walls facing out, the quadtree, GLB bytes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>
#include <set>

#include <glm/geometric.hpp>

#include "buildings/building_height.hpp"
#include "buildings/building_quadtree.hpp"
#include "buildings/extrusion.hpp"
#include "buildings/glb_writer.hpp"
#include "buildings/roof_triangulation.hpp"
#include "geo/ecef.hpp"

namespace globe::buildings {
namespace {

TEST(BuildingHeight, NamedThenHeightThenLevels) {
  EXPECT_EQ(buildingHeight({"31", "12", "4"}, 3).meters, 31.0);
  EXPECT_EQ(buildingHeight({std::nullopt, "12 m", "4"}, 3).meters, 12.0);
  EXPECT_EQ(buildingHeight({std::nullopt, std::nullopt, "4"}, 3).meters, 12.0);
  EXPECT_EQ(buildingHeight({std::nullopt, std::nullopt, "4"}, 3.5).meters, 14.0);
  // A height that does not read as metres falls through to the next field.
  EXPECT_EQ(buildingHeight({std::nullopt, "tall", "2"}, 3).meters, 6.0);
  const BuildingHeight none = buildingHeight({}, 3);
  EXPECT_FALSE(none.meters);
  EXPECT_TRUE(none.problem.empty());
}

TEST(BuildingHeight, AbsurdHeightsAreRefusedWithAReason) {
  for (const char* text : {"1e9", "-5", "0", "1000.5", "nan", "inf", "12 ft", "x"}) {
    const BuildingHeight h = buildingHeight({std::nullopt, text, std::nullopt}, 3);
    EXPECT_FALSE(h.meters) << text;
    EXPECT_FALSE(h.problem.empty()) << text;
  }
  EXPECT_EQ(buildingHeight({std::nullopt, "828", std::nullopt}, 3).meters, 828.0);
  EXPECT_EQ(parseMeters(" 12.5m "), 12.5);
  EXPECT_FALSE(parseMeters(""));
}

double triangleArea(const std::vector<glm::dvec2>& points, const std::vector<uint32_t>& t,
                    size_t i) {
  const glm::dvec2 a = points[t[i]], b = points[t[i + 1]], c = points[t[i + 2]];
  return ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)) / 2;
}

// The triangles' areas: every one counter-clockwise, together the polygon's area.
void expectCovers(const std::vector<PlaneRing>& rings) {
  std::vector<glm::dvec2> points;
  for (const PlaneRing& r : rings) points.insert(points.end(), r.begin(), r.end());
  const std::vector<uint32_t> t = triangulatePolygon(rings);
  ASSERT_EQ(t.size() % 3, 0u);
  double sum = 0;
  for (size_t i = 0; i < t.size(); i += 3) {
    const double area = triangleArea(points, t, i);
    EXPECT_GT(area, 0) << "triangle " << i / 3;
    sum += area;
  }
  EXPECT_NEAR(sum, polygonAreaSquareMeters(rings), 1e-9 * std::abs(sum) + 1e-9);
}

TEST(RoofTriangulation, CoversSquaresWithHolesInEitherWinding) {
  const PlaneRing outer{{0, 0}, {60, 0}, {60, 60}, {0, 60}};
  const PlaneRing hole{{15, 15}, {45, 15}, {45, 45}, {15, 45}};
  expectCovers({outer});
  expectCovers({outer, hole});
  expectCovers({PlaneRing(outer.rbegin(), outer.rend()), hole});
  EXPECT_DOUBLE_EQ(polygonAreaSquareMeters(std::vector<PlaneRing>{outer, hole}), 3600.0 - 900.0);
  // Two holes, one beside the other on the bridges' way, and an L-shaped outer ring.
  const PlaneRing second{{50, 5}, {55, 5}, {55, 10}, {50, 10}};
  expectCovers({outer, hole, second});
  const PlaneRing ell{{0, 0}, {40, 0}, {40, 12}, {12, 12}, {12, 30}, {0, 30}};
  expectCovers({ell});
  expectCovers({ell, PlaneRing{{2, 2}, {8, 2}, {8, 8}, {2, 8}}});
}

TEST(Extrusion, WallsFaceOutAndTheRoofFacesUp) {
  const double lon = 138.8, lat = 35.48;
  const double d = 0.0002;
  Footprint f{{{{lon, lat}, {lon + d, lat}, {lon + d, lat + d}, {lon, lat + d}},
               {{lon + d / 4, lat + d / 4},
                {lon + d / 4, lat + 3 * d / 4},
                {lon + 3 * d / 4, lat + 3 * d / 4},
                {lon + 3 * d / 4, lat + d / 4}}},
              10,
              "courtyard"};
  const geo::Ellipsoid e = geo::Ellipsoid::wgs84();
  BuildingMesh mesh;
  const size_t roofTriangles = appendBuilding(f, 100, 110, e, mesh);
  EXPECT_EQ(roofTriangles, 8u);  // a square ring around a square hole
  EXPECT_EQ(mesh.triangleCount(), 8u + 2 * 8);
  const glm::dvec3 centre =
      geo::cartographicToEcef(e, geo::Cartographic::fromDegrees(lon + d / 2, lat + d / 2, 105));
  const glm::dvec3 up =
      geo::geodeticSurfaceNormal(e, geo::Cartographic::fromDegrees(lon + d / 2, lat + d / 2));
  size_t walls = 0, inner = 0;
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    const glm::dvec3 a = mesh.positionsEcefMeters[mesh.indices[3 * t]];
    const glm::dvec3 b = mesh.positionsEcefMeters[mesh.indices[3 * t + 1]];
    const glm::dvec3 c = mesh.positionsEcefMeters[mesh.indices[3 * t + 2]];
    const glm::dvec3 n = glm::dvec3(mesh.normals[mesh.indices[3 * t]]);
    EXPECT_GT(glm::dot(glm::normalize(glm::cross(b - a, c - a)), n), 0.999) << t;
    if (std::abs(glm::dot(n, up)) > 0.99) continue;  // the roof
    ++walls;
    // Outer walls face away from the centre, the courtyard's towards it.
    const glm::dvec3 mid = (a + b + c) / 3.0;
    const glm::dvec3 away = mid - centre - up * glm::dot(mid - centre, up);
    const bool courtyard = glm::length(away) < 0.3 * d * 111000;
    if (courtyard) ++inner;
    EXPECT_GT(glm::dot(n, away) * (courtyard ? -1 : 1), 0) << t;
  }
  EXPECT_EQ(walls, 16u);
  EXPECT_EQ(inner, 8u);
}

TEST(BuildingQuadtree, EveryBuildingOnceStraddlersStayAbove) {
  std::vector<ExtentDegrees> items;
  for (int i = 0; i < 8; ++i) {
    const double x = 0.1 + 0.1 * i;
    items.push_back({x, 0.1, x + 0.01, 0.11});
  }
  items.push_back({0.49, 0.4, 0.51, 0.41});  // across the root's middle
  const std::vector<QuadtreeCell> cells = partitionBuildings(items, {0, 0, 1, 1}, {2, 12});
  std::multiset<size_t> seen;
  for (const QuadtreeCell& c : cells) seen.insert(c.items.begin(), c.items.end());
  EXPECT_EQ(seen.size(), items.size());
  for (size_t i = 0; i < items.size(); ++i) EXPECT_EQ(seen.count(i), 1u) << i;
  EXPECT_EQ(cells[0].items, std::vector<size_t>{8});
  for (const QuadtreeCell& c : cells) {
    EXPECT_LE(c.items.size(), 2u);
    for (size_t i : c.items) EXPECT_TRUE(c.extent.contains(items[i]));
  }
}

TEST(GlbWriter, AGlbWithItsAccessorsAndTheCentreAsTranslation) {
  BuildingMesh mesh;
  const geo::Ellipsoid e = geo::Ellipsoid::wgs84();
  Footprint f{{{{138.8, 35.48}, {138.8002, 35.48}, {138.8002, 35.4802}}}, 10, "triangle"};
  appendBuilding(f, 0, 10, e, mesh);
  const glm::dvec3 centre =
      geo::cartographicToEcef(e, geo::Cartographic::fromDegrees(138.8, 35.48));
  const std::vector<std::byte> glb = encodeGlb(mesh, centre);
  ASSERT_GT(glb.size(), 28u);
  uint32_t header[5];
  std::memcpy(header, glb.data(), sizeof header);
  EXPECT_EQ(header[0], 0x46546C67u);
  EXPECT_EQ(header[1], 2u);
  EXPECT_EQ(header[2], glb.size());
  EXPECT_EQ(header[4], 0x4E4F534Au);
  const auto* text = reinterpret_cast<const char*>(glb.data()) + 20;
  const nlohmann::json j = nlohmann::json::parse(text, text + header[3]);
  EXPECT_EQ(j["nodes"][0]["translation"][0].get<double>(), centre.x);
  EXPECT_EQ(j["nodes"][0]["translation"][1].get<double>(), centre.z);
  EXPECT_EQ(j["nodes"][0]["translation"][2].get<double>(), -centre.y);
  EXPECT_EQ(j["accessors"][0]["count"].get<size_t>(), mesh.positionsEcefMeters.size());
  EXPECT_EQ(j["accessors"][2]["componentType"].get<int>(), 5125);
  EXPECT_EQ(encodeGlb(mesh, centre), glb);
}

}  // namespace
}  // namespace globe::buildings
