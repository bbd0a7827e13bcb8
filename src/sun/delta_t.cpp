#include "sun/delta_t.hpp"

#include <array>

namespace globe::sun {
namespace {

// The long-term parabola of Morrison and Stephenson, outside the fitted years.
double parabola(double year) {
  const double u = (year - 1820) / 100;
  return -20 + 32 * u * u;
}

// One row per span of years [previous row's end, end): ΔT = c0 + c1·t + c2·t² + ..., t = year −
// origin.
struct Span {
  double endYear, originYear;
  std::array<double, 8> c;
};
constexpr Span kSpans[] = {
    {1860, 1800,
     {13.72, -0.332447, 0.0068612, 0.0041116, -0.00037436, 0.0000121272, -0.0000001699,
      0.000000000875}},
    {1900, 1860, {7.62, 0.5737, -0.251754, 0.01680668, -0.0004473624, 1.0 / 233174}},
    {1920, 1900, {-2.79, 1.494119, -0.0598939, 0.0061966, -0.000197}},
    {1941, 1920, {21.20, 0.84493, -0.076100, 0.0020936}},
    {1961, 1950, {29.07, 0.407, -1.0 / 233, 1.0 / 2547}},
    {1986, 1975, {45.45, 1.067, -1.0 / 260, -1.0 / 718}},
    {2005, 2000, {63.86, 0.3345, -0.060374, 0.0017275, 0.000651814, 0.00002373599}},
    {2050, 2000, {62.92, 0.32217, 0.005589}},
};

}  // namespace

double deltaTSeconds(double year) {
  if (!(year >= 1800)) return parabola(year);  // NaN too
  for (const Span& span : kSpans) {
    if (year >= span.endYear) continue;
    const double t = year - span.originYear;
    double sum = 0;
    for (size_t i = span.c.size(); i-- > 0;) sum = sum * t + span.c[i];
    return sum;
  }
  if (year < 2150) return parabola(year) - 0.5628 * (2150 - year);
  return parabola(year);
}

}  // namespace globe::sun
