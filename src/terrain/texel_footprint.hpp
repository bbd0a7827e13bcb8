// Whether a draped imagery texture is magnified over a whole tile. Where it is, GL's trilinear
// filtering samples the base level only (level of detail <= 0), so a sampler without mipmaps draws
// the same pixels for less: llvmpipe computes no level of detail per fragment (the Zion nadir
// view's frame 13 % cheaper, docs/performance/imagery-frame-time.md).
#pragma once

#include <array>
#include <span>

#include <glm/vec3.hpp>

#include "geo/ellipsoid.hpp"
#include "geo/tile_id.hpp"
#include "terrain/render_view.hpp"

namespace globe::terrain {

// The north-south spacing, in metres, of `intervals` equal steps across `tile` on the meridian
// (radius of curvature b²/a): a terrain tile's sample spacing (verticesPerSide − 1 intervals) or
// an imagery tile's texel (its height in pixels). North-south because east-west both shrink with
// the latitude alike and vanish at the poles. 0 for an invalid tile or no intervals.
double meridianSpacingMeters(const geo::TileId& tile, int intervals,
                             const geo::Ellipsoid& ellipsoid);

// The shortest side, in metres, of one texel of a widthPixels x heightPixels texture covering
// `tile` (geographic tiling scheme): north-south with the smallest meridian radius of curvature
// b²/a, east-west on the smallest parallel radius a·cos(latitude) the tile reaches (0 for a tile
// that touches a pole). 0 for an invalid tile or size.
double shortestTexelMeters(const geo::TileId& tile, int widthPixels, int heightPixels,
                           const geo::Ellipsoid& ellipsoid);

// The angle one pixel subtends at the centre of the view, the larger of its width and its height:
// the largest anywhere on the screen (off-centre pixels subtend less). NaN for a degenerate view.
double pixelAngleRadians(const RenderView& view);

// A box around a tile's vertices in the local frame at its centre: axes[2] is up (the ellipsoid's
// there, geocentric), axes[0] and [1] lie across it (east and north, unit); every vertex lies
// within [minMeters[i], maxMeters[i]] from the centre along axes[i].
struct TileBox {
  glm::dvec3 centerEcefMeters{0.0};
  std::array<glm::dvec3, 3> axes{};
  glm::dvec3 minMeters{0.0};
  glm::dvec3 maxMeters{0.0};
};

// The box of those offsets from the centre (ECEF metres). An empty span or a centre at the
// Earth's centre gives a box maxTexelsPerPixel cannot bound.
TileBox makeTileBox(const glm::dvec3& centerEcefMeters, std::span<const glm::dvec3> offsetsMeters);

// How far a level surface's up turns, at most, between the centre and a point `radiusMeters`
// away: the distance over the smallest radius of curvature b²/a, plus the most the geocentric
// and the geodetic up differ (e²/2, 0.0034 on WGS84), whichever `up` is.
double surfaceTiltRadians(double radiusMeters, const geo::Ellipsoid& ellipsoid);

// An upper bound on GL's scale factor rho (base-level texels per screen pixel) anywhere on a tile
// in the box were its surface level (the ellipsoid's tangent planes, turned by at most
// surfaceTiltRadians from up): a pixel of angle α at distance d spans at most d·α / cos(θ + α)
// metres along such a surface, where cos(θ + α) >= (h/d)·cos(tilt + α) − sin(tilt + α), h = the
// camera's height above the box's top and d <= the distance to the box's farthest corner.
// Slopes steeper than the level surface can exceed it locally (cliffs seen edge-on). +infinity
// where it cannot be bounded: the camera not above the box's top, or an input not finite or not
// positive where it must be.
double maxTexelsPerPixel(const glm::dvec3& cameraEcefMeters, const TileBox& tile,
                         double texelMeters, double pixelAngleRadians,
                         const geo::Ellipsoid& ellipsoid);

}  // namespace globe::terrain
