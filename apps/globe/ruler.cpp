#include "apps/globe/ruler.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

#include <glm/geometric.hpp>

#include "measure/geodesic_path.hpp"

namespace globe::app {
namespace {

std::string format(const char* pattern, auto... values) {
  char text[160];
  std::snprintf(text, sizeof text, pattern, values...);
  return text;
}

// value (>= 0) with enough decimals for three significant digits, then the unit.
std::string significant(double value, const char* unit) {
  const int digits = value > 0 ? static_cast<int>(std::floor(std::log10(value))) + 1 : 1;
  return format("%.*f %s", std::max(0, 3 - digits), value, unit);
}

}  // namespace

void Ruler::setActive(bool active) {
  active_ = active;
  if (!active && !points_.empty()) {
    points_.clear();
    closed_ = false;
    ++revision_;
  }
}

void Ruler::click(const RulerPoint& ground, glm::dvec2 clickPixels,
                  std::optional<glm::dvec2> firstPointPixels) {
  if (closed_) {
    points_.clear();
    closed_ = false;
  } else if (points_.size() >= 3 && firstPointPixels &&
             glm::distance(clickPixels, *firstPointPixels) <= kRulerClosePixels) {
    closed_ = true;
    ++revision_;
    return;
  }
  points_.push_back(ground);
  ++revision_;
}

bool Ruler::undo() {
  if (closed_) {
    closed_ = false;
  } else if (!points_.empty()) {
    points_.pop_back();
  } else {
    return false;
  }
  ++revision_;
  return true;
}

std::vector<measure::PathPoint> Ruler::path() const {
  std::vector<measure::PathPoint> path;
  const double noElevation = std::numeric_limits<double>::quiet_NaN();
  for (const RulerPoint& p : points_) {
    path.push_back({p.longitudeDegrees, p.latitudeDegrees, noElevation});
  }
  if (closed_ && !path.empty()) path.push_back(path.front());
  return path;
}

double Ruler::lengthMeters() const {
  return points_.size() < 2 ? 0.0 : measure::geodesicLengthMeters(path());
}

std::optional<double> Ruler::areaSquareMeters() const {
  if (!closed_) return std::nullopt;
  std::vector<measure::PathPoint> ring = path();
  ring.pop_back();  // ringAreaSquareMeters closes it itself
  return measure::ringAreaSquareMeters(ring);
}

std::string formatLength(double meters) {
  return meters < 10'000 ? significant(meters, "m") : significant(meters / 1000, "km");
}

std::string formatArea(double squareMeters) {
  if (squareMeters < 10'000) return significant(squareMeters, "m2");
  if (squareMeters < 1e6) return significant(squareMeters / 10'000, "ha");
  return significant(squareMeters / 1e6, "km2");
}

std::string rulerHudLine(const Ruler& ruler) {
  const size_t n = ruler.points().size();
  std::string line = "RULER  ";
  if (n == 0) return line + "click the ground to measure  (M ends)";
  line +=
      format("%zu point%s  %s", n, n == 1 ? "" : "s", formatLength(ruler.lengthMeters()).c_str());
  if (const auto area = ruler.areaSquareMeters()) line += "  area " + formatArea(*area);
  return line + (ruler.closed() ? "  (Backspace reopens, M ends)"
                 : n >= 3       ? "  (click the first point closes)"
                                : "  (Backspace undoes, M ends)");
}

std::string rulerLogLine(const Ruler& ruler) {
  std::string line =
      format("ruler: %zu points, %.2f m", ruler.points().size(), ruler.lengthMeters());
  if (const auto area = ruler.areaSquareMeters()) line += format(", area %.1f m2", *area);
  return line;
}

}  // namespace globe::app
