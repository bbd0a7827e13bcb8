// The window's ruler (M, as Google Earth's Ruler): ground points clicked in order make a path
// whose geodesic length is shown; a click back on the first point closes it into a ring whose
// area is shown too. Pure state and text; the loop turns clicks into points and draws the path.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "measure/path_files.hpp"

namespace globe::app {

// A click this close (window pixels) to the first point, with three points or more, closes the
// ring.
inline constexpr double kRulerClosePixels = 10;

struct RulerPoint {
  double longitudeDegrees = 0;
  double latitudeDegrees = 0;
  double heightMeters = 0;  // the drawn ground's, where it was clicked
};

class Ruler {
 public:
  bool active() const { return active_; }
  // On, or off and cleared.
  void setActive(bool active);

  // A click on the ground: closes the ring when it lands near the first point (firstPointPixels:
  // where the first point is drawn now; nullopt: off screen) and the path has three points or
  // more; else adds the point (after a closed ring, as the first of a new path).
  void click(const RulerPoint& ground, glm::dvec2 clickPixels,
             std::optional<glm::dvec2> firstPointPixels);
  // Backspace: reopens a closed ring, else removes the last point; false when empty.
  bool undo();

  const std::vector<RulerPoint>& points() const { return points_; }
  bool closed() const { return closed_; }
  // Bumped by every change, so the loop redraws and reprints only then.
  uint64_t revision() const { return revision_; }

  // The path measured: the points in order, a closed ring's first repeated at its end.
  std::vector<measure::PathPoint> path() const;
  double lengthMeters() const;
  // A closed ring's area; nullopt while open.
  std::optional<double> areaSquareMeters() const;

 private:
  bool active_ = false;
  bool closed_ = false;
  std::vector<RulerPoint> points_;
  uint64_t revision_ = 0;
};

// A length with at least three significant digits: "8.25 m", "812 m", "9345 m", "12.4 km".
std::string formatLength(double meters);
// An area with at least three significant digits in m2 below a hectare, ha below a square
// kilometre, km2 above: "950 m2", "12.5 ha", "31.8 km2".
std::string formatArea(double squareMeters);
// The HUD's line while the ruler is on.
std::string rulerHudLine(const Ruler& ruler);
// What the loop prints on each change: "ruler: N points, LENGTH_M m[, area AREA_M2 m2]".
std::string rulerLogLine(const Ruler& ruler);

}  // namespace globe::app
