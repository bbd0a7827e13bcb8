// The overlays in a scene over the bundled pyramid (Fuji): points placed on the drawn surface and
// hidden behind the mountain; the draped layer added on top of the imagery and replaced when other
// files are opened; lines and walls at an altitude placed at their heights.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>

#include <glm/geometric.hpp>

#include "collision/height_service.hpp"
#include "geo/ecef.hpp"
#include "scene/overlay_points.hpp"
#include "scene/overlay_shapes.hpp"
#include "scene/terrain_scene.hpp"
#include "tests/support/bookkeeping_gpu.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::scene {
namespace {

using overlays::AltitudeMode;
using overlays::Geometry;
using overlays::GeometryKind;

overlays::Placemark placemarkAt(const std::string& name, GeometryKind kind, AltitudeMode mode,
                                std::vector<overlays::Position> points, bool extrude = false) {
  overlays::Placemark placemark;
  placemark.name = name;
  Geometry geometry;
  geometry.kind = kind;
  geometry.altitudeMode = mode;
  geometry.extrude = extrude;
  geometry.rings = {std::move(points)};
  placemark.geometries = {geometry};
  return placemark;
}

struct OpenScene {
  std::unique_ptr<TerrainScene> scene;
  globe::testing::BookkeepingGpu gpu;
};

std::unique_ptr<OpenScene> sceneWith(std::shared_ptr<const overlays::OverlayDocument> document,
                                     const camera::CameraPose& pose) {
  auto open = std::make_unique<OpenScene>();
  SceneOptions options;
  options.hysteresis = false;
  if (document) options.overlays = {document};
  auto scene = TerrainScene::open(globe::testing::bundledPyramid(), options);
  EXPECT_TRUE(scene) << scene.error();
  if (!scene) return nullptr;
  open->scene = std::move(*scene);
  auto frame =
      open->scene->updateUntilComplete(pose, 640, 360, open->gpu, std::chrono::seconds(120));
  EXPECT_TRUE(frame) << frame.error();
  return open;
}

double heightOf(const TerrainScene& scene, const glm::dvec3& ecef) {
  return geo::ecefToCartographic(scene.ellipsoid(), ecef)->heightMeters;
}

// From 2,500 m, 18 km south of Fuji, looking north: the summit shows, a point on the far
// (northern) flank is behind the mountain, a point behind the camera is not on screen.
TEST(OverlayScene, PointsSitOnTheDrawnSurfaceAndHideBehindTheMountain) {
  auto document = std::make_shared<overlays::OverlayDocument>();
  document->placemarks = {placemarkAt("summit", GeometryKind::Point, AltitudeMode::ClampToGround,
                                      {{138.7274, 35.3606, 0}}),
                          placemarkAt("north flank", GeometryKind::Point,
                                      AltitudeMode::ClampToGround, {{138.7300, 35.4200, 0}}),
                          placemarkAt("behind", GeometryKind::Point, AltitudeMode::ClampToGround,
                                      {{138.7300, 35.1000, 0}}),
                          placemarkAt("above", GeometryKind::Point, AltitudeMode::RelativeToGround,
                                      {{138.7274, 35.3606, 500}})};
  const auto pose = camera::CameraPose::fromDegrees(138.7274, 35.20, 2500, 0, -3, 0);
  auto open = sceneWith(document, pose);
  ASSERT_TRUE(open);
  const TerrainScene& scene = *open->scene;
  ASSERT_EQ(scene.pointMarks().size(), 4u);
  const auto shown =
      shownPoints(scene.pointMarks(), scene.view(), scene.renderingTileArray(), scene.ellipsoid());
  std::vector<std::string> names;
  for (const ShownPoint& point : shown) names.push_back(document->placemarks[point.mark].name);
  EXPECT_EQ(names, (std::vector<std::string>{"summit", "above"}));
  ASSERT_EQ(shown.size(), 2u);
  const auto ground = collision::sampleHeight(
      scene.renderingTileArray(), scene.ellipsoid(), geo::degreesToRadians(138.7274),
      geo::degreesToRadians(35.3606), collision::HeightMode::Exact);
  ASSERT_TRUE(ground);
  EXPECT_GT(ground->heightMeters, 3400);  // the summit as drawn now
  EXPECT_NEAR(heightOf(scene, shown[0].ecefMeters), ground->heightMeters, 0.01);
  EXPECT_NEAR(heightOf(scene, shown[1].ecefMeters), ground->heightMeters + 500, 0.01);
  // Straight ahead, above the horizon line's middle: the summit is near the centre column.
  EXPECT_NEAR(shown[0].anchorPixels.x, 320, 5);
  EXPECT_LT(shown[1].anchorPixels.y, shown[0].anchorPixels.y);
  // The hidden point is there on the surface; only the mountain hides it.
  const auto flank = geo::cartographicToEcef(scene.ellipsoid(),
                                             geo::Cartographic::fromDegrees(138.73, 35.42, 1500));
  EXPECT_TRUE(hiddenByTerrain(scene.view().cameraEcefMeters, flank, scene.renderingTileArray(),
                              scene.ellipsoid()));
  const auto highAbove = geo::cartographicToEcef(
      scene.ellipsoid(), geo::Cartographic::fromDegrees(138.73, 35.42, 8000));
  EXPECT_FALSE(hiddenByTerrain(scene.view().cameraEcefMeters, highAbove, scene.renderingTileArray(),
                               scene.ellipsoid()));
  // The antipode is behind the globe.
  const auto antipode = geo::cartographicToEcef(
      scene.ellipsoid(), geo::Cartographic::fromDegrees(138.73 - 180, -35.36, 0));
  EXPECT_TRUE(hiddenByTerrain(scene.view().cameraEcefMeters, antipode, scene.renderingTileArray(),
                              scene.ellipsoid()));
}

TEST(OverlayScene, TheDrapedLayerGoesOnTopAndIsReplacedByOtherFiles) {
  auto document = std::make_shared<overlays::OverlayDocument>();
  document->placemarks = {placemarkAt("trail", GeometryKind::LineString,
                                      AltitudeMode::ClampToGround,
                                      {{138.70, 35.36, 0}, {138.76, 35.36, 0}})};
  const auto pose = camera::CameraPose::fromDegrees(138.73, 35.36, 20000, 0, -90, 0);
  auto open = sceneWith(document, pose);
  ASSERT_TRUE(open);
  TerrainScene& scene = *open->scene;
  ASSERT_EQ(scene.overlayLayer(), std::optional<uint32_t>(0));
  const auto drapedOn = [&](uint32_t layer) {
    size_t count = 0;
    for (const terrain::TileDrapes& drapes : scene.drapes()) {
      for (uint32_t k = 0; k < drapes.count; ++k) count += drapes.layers[k].layer == layer;
    }
    return count;
  };
  const size_t before = drapedOn(0);
  EXPECT_GT(before, 0u);
  EXPECT_LT(before, scene.tiles().size()) << "only tiles near the line";
  const size_t texturesBefore = open->gpu.imageryTilesResident();
  EXPECT_GT(texturesBefore, 0u);

  // Another file far away: the old textures go, nothing is draped here any more.
  auto elsewhere = std::make_shared<overlays::OverlayDocument>();
  elsewhere->placemarks = {placemarkAt("far", GeometryKind::LineString, AltitudeMode::ClampToGround,
                                       {{10, 10, 0}, {11, 11, 0}})};
  ASSERT_TRUE(scene.setOverlays({elsewhere}, open->gpu));
  EXPECT_EQ(scene.overlayLayer(), std::optional<uint32_t>(0));
  ASSERT_TRUE(scene.updateUntilComplete(pose, 640, 360, open->gpu, std::chrono::seconds(120)));
  EXPECT_EQ(drapedOn(0), 0u);
  EXPECT_TRUE(scene.pointMarks().empty());
}

// A file opened over a complete view (the window's O): while its tiles are made, the ground never
// takes a coarser overlay tile's texels (a line 2^k times as wide, flooding the ground with its
// colour); each terrain tile drapes its own overlay tile or none, the one the final frame drapes.
TEST(OverlayScene, AnOpenedFileNeverDrapesACoarserTilesLines) {
  const auto pose = camera::CameraPose::fromDegrees(138.73, 35.36, 20000, 0, -90, 0);
  auto open = sceneWith(nullptr, pose);
  ASSERT_TRUE(open);
  TerrainScene& scene = *open->scene;
  auto document = std::make_shared<overlays::OverlayDocument>();
  document->placemarks = {placemarkAt("trail", GeometryKind::LineString,
                                      AltitudeMode::ClampToGround,
                                      {{138.70, 35.36, 0}, {138.76, 35.37, 0}})};
  ASSERT_TRUE(scene.setOverlays({document}, open->gpu));
  ASSERT_TRUE(scene.overlayLayer());
  const uint32_t layer = *scene.overlayLayer();
  using Mapping = std::map<geo::TileId, geo::TileId>;  // terrain tile → overlay tile draped
  auto mapping = [&] {
    Mapping drawn;
    for (size_t i = 0; i < scene.tiles().size() && i < scene.drapes().size(); ++i) {
      const terrain::TileDrapes& drapes = scene.drapes()[i];
      for (uint32_t k = 0; k < drapes.count; ++k) {
        if (drapes.layers[k].layer == layer) drawn[scene.tiles()[i]] = drapes.layers[k].imageryTile;
      }
    }
    return drawn;
  };
  std::vector<Mapping> frames;
  for (int f = 0; f < 200; ++f) {
    const FrameInfo info = scene.update(pose, 640, 360, open->gpu);
    frames.push_back(mapping());
    if (info.complete) break;
    scene.waitForLoads(std::chrono::milliseconds(50));
  }
  const Mapping final = mapping();
  ASSERT_FALSE(final.empty()) << "the line is draped";
  for (size_t f = 0; f < frames.size(); ++f) {
    for (const auto& [tile, drawn] : frames[f]) {
      const auto last = final.find(tile);
      ASSERT_NE(last, final.end()) << "frame " << f << ": " << geo::tileName(tile);
      EXPECT_EQ(drawn, last->second) << "frame " << f << ": " << geo::tileName(tile) << " drapes "
                                     << geo::tileName(drawn);
    }
  }
}

TEST(OverlayScene, ShapesAtAnAltitudeStandAtTheirHeights) {
  auto document = std::make_shared<overlays::OverlayDocument>();
  document->placemarks = {
      placemarkAt("flight", GeometryKind::LineString, AltitudeMode::Absolute,
                  {{138.66, 35.30, 5000}, {138.70, 35.33, 5000}, {138.74, 35.34, 5000}}, true),
      placemarkAt("tower", GeometryKind::Polygon, AltitudeMode::RelativeToGround,
                  {{138.76, 35.39, 800},
                   {138.77, 35.39, 800},
                   {138.77, 35.40, 800},
                   {138.76, 35.40, 800},
                   {138.76, 35.39, 800}},
                  true),
      placemarkAt("on the ground", GeometryKind::LineString, AltitudeMode::ClampToGround,
                  {{138.7, 35.3, 0}, {138.8, 35.3, 0}})};
  EXPECT_TRUE(hasShapes3d(std::vector<std::shared_ptr<const overlays::OverlayDocument>>{document}));
  const auto pose = camera::CameraPose::fromDegrees(138.72, 35.25, 9000, 0, -30, 0);
  auto open = sceneWith(document, pose);
  ASSERT_TRUE(open);
  const TerrainScene& scene = *open->scene;
  const OverlayShapes3d shapes =
      overlayShapes3d(scene.options().overlays, scene.renderingTileArray(), scene.ellipsoid());
  // The flight and the tower's outline; the clamped line is draped, not here.
  ASSERT_EQ(shapes.lines.size(), 2u);
  for (const glm::dvec3& p : shapes.lines[0].ecefMeters)
    EXPECT_NEAR(heightOf(scene, p), 5000, 1e-3);
  // The flight's wall (2 segments), the tower's roof (2 triangles) and its walls (4 sides).
  ASSERT_EQ(shapes.triangles.size(), 3u);
  EXPECT_EQ(shapes.triangles[0].ecefMeters.size(), 2u * 6);
  EXPECT_EQ(shapes.triangles[1].ecefMeters.size(), 2u * 3);
  EXPECT_EQ(shapes.triangles[2].ecefMeters.size(), 4u * 6);
  for (const glm::dvec3& p : shapes.lines[1].ecefMeters) {
    const auto c = geo::ecefToCartographic(scene.ellipsoid(), p);
    const auto ground =
        collision::sampleHeight(scene.renderingTileArray(), scene.ellipsoid(), c->longitudeRadians,
                                c->latitudeRadians, collision::HeightMode::Exact);
    ASSERT_TRUE(ground);
    EXPECT_NEAR(c->heightMeters, ground->heightMeters + 800, 0.01);
  }
  // The wall's feet stand on the drawn ground.
  const glm::dvec3 foot = shapes.triangles[0].ecefMeters[1];
  const auto c = geo::ecefToCartographic(scene.ellipsoid(), foot);
  const auto ground =
      collision::sampleHeight(scene.renderingTileArray(), scene.ellipsoid(), c->longitudeRadians,
                              c->latitudeRadians, collision::HeightMode::Exact);
  ASSERT_TRUE(ground);
  EXPECT_NEAR(c->heightMeters, ground->heightMeters, 0.01);
}

}  // namespace
}  // namespace globe::scene
