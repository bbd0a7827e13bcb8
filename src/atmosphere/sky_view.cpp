#include "atmosphere/sky_view.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>

namespace globe::atmosphere {
namespace {

constexpr int kViewSteps = 32;
constexpr double kHalfPi = std::numbers::pi / 2.0;

// Where a ray from radius r along zenith cosine mu is in the air: [start, end] metres.
struct Span {
  double start = 0.0, end = -1.0;
  bool ground = false;
};
Span airAlong(const Atmosphere& a, double r, double mu) {
  Span span;
  if (r > a.topRadiusMeters) {
    span.start = distanceToSphere(r, mu, a.topRadiusMeters);
    if (span.start < 0.0) return span;  // misses the air
  }
  span.ground = hitsGround(a, r, mu);
  const double b = r * mu, top = a.topRadiusMeters;
  span.end = span.ground ? distanceToSphere(r, mu, a.groundRadiusMeters)
                         : -b + std::sqrt(std::max(b * b - (r * r - top * top), 0.0));  // the exit
  return span;
}

}  // namespace

glm::dvec3 skyRadiance(const SkyTables& tables, double r, const glm::dvec3& direction,
                       const glm::dvec3& sun) {
  const Atmosphere& a = tables.atmosphere();
  r = std::max(r, a.groundRadiusMeters + 1.0);
  const Span span = airAlong(a, r, direction.z);
  if (span.end <= span.start) return glm::dvec3(0.0);
  const double cosine = glm::dot(direction, sun);
  const double rayleigh = rayleighPhase(cosine), mie = miePhase(cosine, a.mieAsymmetry);
  const double step = (span.end - span.start) / kViewSteps;
  glm::dvec3 throughput(1.0), light(0.0);
  for (int k = 0; k < kViewSteps; ++k) {
    const glm::dvec3 p = glm::dvec3(0.0, 0.0, r) + (span.start + (k + 0.5) * step) * direction;
    const double radius = glm::length(p);
    const Medium m = mediumAt(a, radius - a.groundRadiusMeters);
    const double sunMu = glm::dot(p, sun) / radius;
    const glm::dvec3 single = tables.transmittance(radius, sunMu) *
                              (m.rayleighScattering * rayleigh + glm::dvec3(m.mieScattering * mie));
    const glm::dvec3 multiple = tables.multipleScattering(radius, sunMu) *
                                (m.rayleighScattering + glm::dvec3(m.mieScattering));
    const glm::dvec3 stepTransmittance = glm::exp(-m.extinction * step);
    const glm::dvec3 integral =
        (glm::dvec3(1.0) - stepTransmittance) / glm::max(m.extinction, glm::dvec3(1e-12));
    light += throughput * (single + multiple) * integral;
    throughput *= stepTransmittance;
  }
  return light;
}

double horizonElevation(const Atmosphere& a, double r) {
  // The tangent to the ground leaves the camera acos(ground / r) below the horizontal.
  return -std::acos(std::clamp(a.groundRadiusMeters / std::max(r, a.groundRadiusMeters), 0.0, 1.0));
}

double skyViewElevation(double v, double h) {
  if (v < 0.5) {
    const double l = 1.0 - 2.0 * v;
    return h - l * l * (h + kHalfPi);
  }
  const double l = 2.0 * v - 1.0;
  return h + l * l * (kHalfPi - h);
}

double skyViewRow(double e, double h) {
  if (e < h) return 0.5 * (1.0 - std::sqrt(std::clamp((h - e) / (h + kHalfPi), 0.0, 1.0)));
  return 0.5 * (1.0 + std::sqrt(std::clamp((e - h) / (kHalfPi - h), 0.0, 1.0)));
}

glm::dvec3 toneMapped(const glm::dvec3& radiance) {
  const glm::dvec3 exposed = glm::dvec3(1.0) - glm::exp(-kSkyExposure * radiance);
  return glm::pow(glm::clamp(exposed, 0.0, 1.0), glm::dvec3(1.0 / 2.2));
}

glm::dvec3 SkyViewImage::at(double u, double v) const {
  const double x = std::clamp(u, 0.0, 1.0) * (width - 1),
               y = std::clamp(v, 0.0, 1.0) * (height - 1);
  const int x0 = std::min(static_cast<int>(x), width - 2),
            y0 = std::min(static_cast<int>(y), height - 2);
  const double fx = x - x0, fy = y - y0;
  auto texel = [&](int c, int r) {
    const size_t i = 4 * (static_cast<size_t>(r) * width + c);
    return glm::dvec3(rgba[i], rgba[i + 1], rgba[i + 2]) / 255.0;
  };
  return (texel(x0, y0) * (1 - fx) + texel(x0 + 1, y0) * fx) * (1 - fy) +
         (texel(x0, y0 + 1) * (1 - fx) + texel(x0 + 1, y0 + 1) * fx) * fy;
}

SkyViewImage skyView(const SkyTables& tables, double cameraRadiusMeters, double sunZenithCosine,
                     int width, int height) {
  SkyViewImage image;
  image.width = std::max(width, 2);
  image.height = std::max(height, 2);
  image.cameraRadiusMeters = cameraRadiusMeters;
  image.horizonElevationRadians = horizonElevation(tables.atmosphere(), cameraRadiusMeters);
  const double sunMu = std::clamp(sunZenithCosine, -1.0, 1.0);
  const glm::dvec3 sun(std::sqrt(1.0 - sunMu * sunMu), 0.0, sunMu);
  image.rgba.resize(4 * static_cast<size_t>(image.width) * image.height);
  for (int row = 0; row < image.height; ++row) {
    const double elevation = skyViewElevation(static_cast<double>(row) / (image.height - 1),
                                              image.horizonElevationRadians);
    for (int column = 0; column < image.width; ++column) {
      const double azimuth = std::numbers::pi * column / (image.width - 1);
      const glm::dvec3 direction(std::cos(elevation) * std::cos(azimuth),
                                 std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
      const glm::dvec3 colour = toneMapped(skyRadiance(tables, cameraRadiusMeters, direction, sun));
      const size_t i = 4 * (static_cast<size_t>(row) * image.width + column);
      for (int c = 0; c < 3; ++c) {
        image.rgba[i + c] = static_cast<uint8_t>(std::lround(255.0 * colour[c]));
      }
      image.rgba[i + 3] = 255;
    }
  }
  return image;
}

}  // namespace globe::atmosphere
