// Conversions between geodetic coordinates and earth-centred earth-fixed (ECEF) positions.
// ECEF: x towards (0 deg, 0 deg), y towards (90 deg E, 0 deg), z towards the north pole; metres.
#pragma once

#include <optional>

#include <glm/vec3.hpp>

#include "geo/cartographic.hpp"
#include "geo/ellipsoid.hpp"

namespace globe::geo {

// Positions closer than this to the centre have no defined longitude/latitude.
inline constexpr double kGeocentreThresholdMeters = 1e-9;

glm::dvec3 cartographicToEcef(const Ellipsoid& ellipsoid, const Cartographic& cartographic);

// Inverse of cartographicToEcef, accurate to well below a micrometre from -11 km to beyond 4e7 m
// height. nullopt ("undefined") when any component is non-finite, when the position is within
// kGeocentreThresholdMeters of the centre, or when the result would overflow; never NaN.
// Longitude is in [-pi, pi], latitude in [-pi/2, pi/2]. Deep inside the ellipsoid (within ~43 km
// of the centre on WGS84) the geodetic latitude is not unique; one valid answer is returned.
std::optional<Cartographic> ecefToCartographic(const Ellipsoid& ellipsoid,
                                               const glm::dvec3& ecefMeters);

// ecefToCartographic and the unit ellipsoid normal at the result, taken from the same iteration
// (no sines or cosines; equal to geodeticSurfaceNormal(cartographic) to ~1e-16): what a test
// along the normal needs. nullopt where ecefToCartographic is.
struct GeodeticFrame {
  Cartographic cartographic;
  glm::dvec3 normal;
};
std::optional<GeodeticFrame> ecefToGeodeticFrame(const Ellipsoid& ellipsoid,
                                                 const glm::dvec3& ecefMeters);

// Unit "up" vector (the ellipsoid normal) at a geodetic position.
glm::dvec3 geodeticSurfaceNormal(const Ellipsoid& ellipsoid, const Cartographic& cartographic);
// Unit "up" vector at an ECEF position: the ellipsoid normal through its nadir, at any height.
// Where ecefToCartographic is undefined (geocentre, non-finite input) returns +z.
glm::dvec3 geodeticSurfaceNormal(const Ellipsoid& ellipsoid, const glm::dvec3& ecefMeters);

}  // namespace globe::geo
