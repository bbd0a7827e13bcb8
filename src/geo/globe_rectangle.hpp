// A longitude/latitude rectangle on the globe (the footprint of a tile); never crosses the
// antimeridian, so west <= east always.
#pragma once

#include "geo/cartographic.hpp"

namespace globe::geo {

struct GlobeRectangle {
  double westRadians;
  double southRadians;
  double eastRadians;
  double northRadians;

  static GlobeRectangle fromDegrees(double westDegrees, double southDegrees, double eastDegrees,
                                    double northDegrees);

  double widthRadians() const { return eastRadians - westRadians; }
  double heightRadians() const { return northRadians - southRadians; }
  // Midpoint in longitude and latitude, at height 0.
  Cartographic center() const;
  // Closed: points on the edges are contained.
  bool contains(double longitudeRadians, double latitudeRadians) const;
  // Closed: rectangles sharing only an edge or a corner intersect.
  bool intersects(const GlobeRectangle& other) const;
};

}  // namespace globe::geo
