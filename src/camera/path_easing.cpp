// CSS cubic-Bézier easing (path_easing.hpp).
#include "camera/path_easing.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace globe::camera {
namespace {

constexpr std::array<std::pair<std::string_view, CubicBezierEase>, 4> kNamed = {{
    {"linear", kEaseLinear},
    {"in", kEaseIn},
    {"out", kEaseOut},
    {"inOut", kEaseInOut},
}};

// One coordinate of the Bézier from 0 to 1 through control values a and b, and its derivative.
double bezier(double a, double b, double s) {
  const double t = 1.0 - s;
  return 3.0 * t * t * s * a + 3.0 * t * s * s * b + s * s * s;
}
double bezierSlope(double a, double b, double s) {
  const double t = 1.0 - s;
  return 3.0 * t * t * a + 6.0 * t * s * (b - a) + 3.0 * s * s * (1.0 - b);
}

}  // namespace

std::optional<CubicBezierEase> namedEase(std::string_view name) {
  for (const auto& [known, ease] : kNamed) {
    if (known == name) return ease;
  }
  return std::nullopt;
}

std::string_view easeName(const CubicBezierEase& ease) {
  for (const auto& [known, curve] : kNamed) {
    if (curve == ease) return known;
  }
  return "";
}

double easeProgress(const CubicBezierEase& ease, double x) {
  if (!(x > 0.0)) return 0.0;
  if (x >= 1.0) return 1.0;
  double s = x, low = 0.0, high = 1.0;
  for (int i = 0; i < 64; ++i) {
    const double error = bezier(ease.x1, ease.x2, s) - x;
    if (std::abs(error) < 1e-12) break;
    if (error > 0) high = s;
    else low = s;
    const double slope = bezierSlope(ease.x1, ease.x2, s);
    const double next = slope > 1e-9 ? s - error / slope : -1.0;
    s = next > low && next < high ? next : 0.5 * (low + high);  // bisect where Newton leaves
  }
  return bezier(ease.y1, ease.y2, s);
}

}  // namespace globe::camera
