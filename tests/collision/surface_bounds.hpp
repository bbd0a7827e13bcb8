// How far the exact drawn surface E may lie from a tile's vertex heights, for tests comparing
// QOTCD's H with E: the row-sliver allowance (E above H) and the chord sag (E below the vertices).
#pragma once

#include "collision/terrain_array.hpp"
#include "geo/ellipsoid.hpp"

namespace globe::collision::testing {

// The one way H can fall below the rendered surface, by geometry rather than rounding: a mesh
// row edge is a chord, which runs poleward of its parallel by up to
// b = a |sin(lat) cos(lat)| dLon^2 / 8, so next to a row line the ray can meet a triangle of the
// quad across it (exact_surface.hpp), whose plane climbs at most s b over that distance (s: the
// steepest north-south step between the vertices around the point, per metre), while the chord
// itself sags a cos^2(lat) dLon^2 / 8 below its ends. So H - E >= -s b (+ rounding); 10% margin
// for the ellipsoid's radii of curvature.
double rowSliverAllowanceMeters(const ArrayTile& tile, double latitudeRadians,
                                const geo::Ellipsoid& ellipsoid);

// A loose lower bound on how far a triangle's plane can sag below its lowest vertex height, for
// points in (or a rounding hair outside) the triangle: a convex combination of points at radius
// >= r spread over an angle <= t lies at radius >= r cos t, t <= the cell's diagonal angle
// (dLat^2 + dLon^2)^(1/2), so the sag is <= a t^2 / 2; plus (a - b) t for the ellipsoid's change
// of radius across the cell. Level 0: ~250 km (the real sag is ~30 km); level 14: ~2 mm.
double chordSagBoundMeters(const ArrayTile& tile, const geo::Ellipsoid& ellipsoid);

}  // namespace globe::collision::testing
