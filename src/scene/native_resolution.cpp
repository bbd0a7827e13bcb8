#include "scene/native_resolution.hpp"

#include <cmath>
#include <limits>

#include "geo/cartographic.hpp"
#include "geo/tiling_scheme.hpp"

namespace globe::scene {
namespace {

struct PointDegrees {
  double longitudeDegrees, latitudeDegrees;
};

PointDegrees centreOf(const geo::TileId& tile) {
  const auto rect = geo::GeographicTilingScheme::tileRectangle(tile);
  return {geo::radiansToDegrees(rect.westRadians + rect.widthRadians() / 2),
          geo::radiansToDegrees(rect.southRadians + rect.heightRadians() / 2)};
}

bool holds(const formats::BoundsDegrees& b, const PointDegrees& c) {
  if (!(c.latitudeDegrees >= b.south && c.latitudeDegrees <= b.north)) return false;
  // The longitude, moved by whole turns to the first one at or east of the west edge.
  double lon = c.longitudeDegrees;
  while (lon < b.west) lon += 360.0;
  while (lon - 360.0 >= b.west) lon -= 360.0;
  const double east = b.east < b.west ? b.east + 360.0 : b.east;
  return lon <= east;
}

template <class Source, class Step>
double finestAt(std::span<const Source> sources, const PointDegrees& point, Step step) {
  double finest = std::numeric_limits<double>::quiet_NaN();
  for (const Source& source : sources) {
    const double degrees = step(source);
    if (!(degrees > 0.0) || !std::isfinite(degrees) || !holds(source.bounds, point)) continue;
    if (!(degrees >= finest)) finest = degrees;  // NaN compares false: the first one wins
  }
  return finest;
}

}  // namespace

double finestStepDegreesAt(std::span<const formats::SourceInfo> sources, double longitudeDegrees,
                           double latitudeDegrees) {
  return finestAt(sources, PointDegrees{longitudeDegrees, latitudeDegrees},
                  [](const formats::SourceInfo& s) { return s.stepDegrees; });
}

double finestStepDegreesAt(std::span<const formats::SourceInfo> sources, const geo::TileId& tile) {
  const PointDegrees centre = centreOf(tile);
  return finestStepDegreesAt(sources, centre.longitudeDegrees, centre.latitudeDegrees);
}

std::array<double, 4> finestStepDegreesAtCorners(std::span<const formats::SourceInfo> sources,
                                                 const geo::TileId& tile) {
  const auto rect = geo::GeographicTilingScheme::tileRectangle(tile);
  const double west = geo::radiansToDegrees(rect.westRadians);
  const double east = geo::radiansToDegrees(rect.westRadians + rect.widthRadians());
  const double south = geo::radiansToDegrees(rect.southRadians);
  const double north = geo::radiansToDegrees(rect.southRadians + rect.heightRadians());
  return {finestStepDegreesAt(sources, west, north), finestStepDegreesAt(sources, east, north),
          finestStepDegreesAt(sources, west, south), finestStepDegreesAt(sources, east, south)};
}

double finestTexelDegreesAt(std::span<const formats::ImagerySourceInfo> sources,
                            const geo::TileId& tile) {
  return finestAt(sources, centreOf(tile),
                  [](const formats::ImagerySourceInfo& s) { return s.pixelDegrees; });
}

}  // namespace globe::scene
