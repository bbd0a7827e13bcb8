// GlobeRectangle queries.
#include "geo/globe_rectangle.hpp"

namespace globe::geo {

GlobeRectangle GlobeRectangle::fromDegrees(double westDegrees, double southDegrees,
                                           double eastDegrees, double northDegrees) {
  return {degreesToRadians(westDegrees), degreesToRadians(southDegrees),
          degreesToRadians(eastDegrees), degreesToRadians(northDegrees)};
}

Cartographic GlobeRectangle::center() const {
  return {0.5 * (westRadians + eastRadians), 0.5 * (southRadians + northRadians), 0.0};
}

bool GlobeRectangle::contains(double longitudeRadians, double latitudeRadians) const {
  return longitudeRadians >= westRadians && longitudeRadians <= eastRadians &&
         latitudeRadians >= southRadians && latitudeRadians <= northRadians;
}

bool GlobeRectangle::intersects(const GlobeRectangle& other) const {
  return westRadians <= other.eastRadians && other.westRadians <= eastRadians &&
         southRadians <= other.northRadians && other.southRadians <= northRadians;
}

}  // namespace globe::geo
