// Picking a draped placemark at a ground point: lines within the tolerance, polygons by even-odd
// cover (holes excluded), lines over polygons, hidden placemarks never, the antimeridian.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "overlays/overlay_pick.hpp"

namespace globe::overlays {
namespace {

Position pickAt(double lon, double lat) { return {lon, lat, 0}; }

Placemark withGeometry(GeometryKind kind, std::vector<std::vector<Position>> rings) {
  Placemark placemark;
  Geometry geometry;
  geometry.kind = kind;
  geometry.rings = std::move(rings);
  placemark.geometries = {geometry};
  return placemark;
}

TEST(OverlayPick, LinesPolygonsHolesAndOrder) {
  auto document = std::make_shared<OverlayDocument>();
  // 0: a square 0..1° with a hole 0.4..0.6°; 1: a line along 0.5° N across it.
  document->placemarks.push_back(
      withGeometry(GeometryKind::Polygon,
                   {{pickAt(0, 0), pickAt(1, 0), pickAt(1, 1), pickAt(0, 1), pickAt(0, 0)},
                    {pickAt(0.4, 0.4), pickAt(0.6, 0.4), pickAt(0.6, 0.6), pickAt(0.4, 0.6),
                     pickAt(0.4, 0.4)}}));
  document->placemarks.push_back(
      withGeometry(GeometryKind::LineString, {{pickAt(-1, 0.5), pickAt(2, 0.5)}}));
  const std::shared_ptr<const OverlayDocument> documents[] = {document};

  EXPECT_EQ(pickDraped(documents, 0.2, 0.2, 10), (PlacemarkRef{0, 0}));
  EXPECT_EQ(pickDraped(documents, 0.5, 0.45, 10), std::nullopt);  // in the hole, off the line
  // 0.5° N ± 50 m: the line, drawn over the polygon, wins.
  EXPECT_EQ(pickDraped(documents, 0.2, 0.5004, 100), (PlacemarkRef{0, 1}));
  EXPECT_EQ(pickDraped(documents, -0.5, 0.5004, 100), (PlacemarkRef{0, 1}));
  EXPECT_EQ(pickDraped(documents, -0.5, 0.51, 100), std::nullopt);  // 1.1 km off
  EXPECT_EQ(pickDraped(documents, 5, 5, 100), std::nullopt);

  document->placemarks[1].visible = false;
  EXPECT_EQ(pickDraped(documents, 0.2, 0.5004, 100), (PlacemarkRef{0, 0}));
  EXPECT_EQ(pickDraped(documents, std::nan(""), 0, 100), std::nullopt);
}

TEST(OverlayPick, AcrossTheAntimeridian) {
  auto document = std::make_shared<OverlayDocument>();
  document->placemarks.push_back(
      withGeometry(GeometryKind::LineString, {{pickAt(179.5, -17), pickAt(-179.5, -17)}}));
  const std::shared_ptr<const OverlayDocument> documents[] = {document};
  EXPECT_EQ(pickDraped(documents, 180.0, -17.0, 50), (PlacemarkRef{0, 0}));
  EXPECT_EQ(pickDraped(documents, -179.9, -17.0, 50), (PlacemarkRef{0, 0}));
  EXPECT_EQ(pickDraped(documents, 0, -17.0, 50), std::nullopt);
}

}  // namespace
}  // namespace globe::overlays
