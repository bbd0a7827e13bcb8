// Easing of a path segment, as CSS writes it: a cubic Bézier from (0, 0) to (1, 1) through the
// control points (x1, y1) and (x2, y2), x the segment's time fraction and y how far along its way
// the camera is. A keyframe's ease shapes the segment that leaves it.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace globe::camera {

struct CubicBezierEase {
  double x1 = 0, y1 = 0, x2 = 1, y2 = 1;  // x1 and x2 in 0..1 (x is then monotone)
  bool operator==(const CubicBezierEase&) const = default;
};

// CSS's named curves: linear, ease-in, ease-out and ease-in-out.
inline constexpr CubicBezierEase kEaseLinear{0.0, 0.0, 1.0, 1.0};
inline constexpr CubicBezierEase kEaseIn{0.42, 0.0, 1.0, 1.0};
inline constexpr CubicBezierEase kEaseOut{0.0, 0.0, 0.58, 1.0};
inline constexpr CubicBezierEase kEaseInOut{0.42, 0.0, 0.58, 1.0};

// "linear", "in", "out", "inOut"; nullopt for any other name.
std::optional<CubicBezierEase> namedEase(std::string_view name);
// The name of a named curve, else "" (written as its four numbers).
std::string_view easeName(const CubicBezierEase& ease);

// y at x (clamped to 0..1): x(s) solved for s by Newton's method, bisection where it stalls, to
// 1e-12. Monotone in x when y1 and y2 are in 0..1; overshoots (y outside 0..1) are allowed, as
// in CSS.
double easeProgress(const CubicBezierEase& ease, double x);

}  // namespace globe::camera
