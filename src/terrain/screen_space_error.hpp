// The level-of-detail metric of tile selection: a tile's geometric error, the camera's distance
// to its bounding region, and the error's size on screen in pixels.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "geo/bounding_region.hpp"
#include "geo/ellipsoid.hpp"
#include "terrain/selection_view.hpp"

namespace globe::terrain {

// The fraction of a tile's vertex spacing taken as its geometric error, as cesium-native's
// heightmap quadtrees do (calcQuadtreeMaxGeometricError: 25% of the sample spacing at the
// equator): a regular grid misrepresents terrain between its vertices by about
// slope x spacing / 2, and typical slopes (0.1 to 0.5) give about a quarter of the spacing.
// With a 2-pixel threshold a tile is drawn when its vertices lie ~8 pixels apart.
inline constexpr double kTerrainQuality = 0.25;

// Distances below this count as this distance, so the screen-space error stays finite and a
// camera inside (or touching) a tile's region refines it down to the pyramid's deepest level.
inline constexpr double kMinimumDistanceMeters = 1.0;

// kTerrainQuality x the vertex spacing of the level along the equator:
// 0.25 x a x pi / (2^level x (verticesPerSide - 1)). The equator has the widest spacing, so the
// error is an upper bound for the whole level (17 vertices on WGS84: 313 km at level 0, 19 m at
// level 14). verticesPerSide below 2 counts as 2.
double geometricErrorMeters(uint32_t level, uint32_t verticesPerSide,
                            const geo::Ellipsoid& ellipsoid);

// How far below the nominal error a measured one may take a tile seen face-on. The hill-shading
// shows the terrain's slopes, which a small height deviation can hide: seen from above, smooth
// ground drawn from vertices much further apart than the nominal ~8 px shows its LOD boundaries
// (tests/render/test_shading_seams.cpp). Seen at a grazing angle, the spacing is foreshortened
// and what shows is the height error on the silhouettes: there the measured error counts.
inline constexpr double kMeasuredErrorFloor = 0.25;
// Tiles coarser than this keep the nominal error: they are few, and their bounding volumes are
// loose (a refined tile's children cull what the whole tile cannot).
inline constexpr uint32_t kMeasuredErrorMinimumLevel = 6;

// The error selection uses for a tile: geometricErrorMeters of its level, or less where the tiler
// measured less (smooth land, open sea): measured + the sag of a chord between the tile's
// vertices below the curved surface, s²/(8a) for the vertex spacing s along a meridian, but at
// least the nominal times max(kMeasuredErrorFloor, faceOn). faceOn in [0, 1]: the cosine between
// the tile's up and the direction to the camera where it is largest (1: seen from straight
// above, 0: edge-on); NaN counts as 1. A measured error that is NaN, negative or infinite counts
// as unknown, and so does any below kMeasuredErrorMinimumLevel: the nominal.
double tileGeometricErrorMeters(uint32_t level, uint32_t verticesPerSide,
                                const geo::Ellipsoid& ellipsoid,
                                double measuredGeometricErrorMeters, double faceOn = 1.0);

// The largest cosine between the surface's up (the geodetic normal) and the direction to the
// camera over the points, clamped to [0, 1]: how face-on a region is seen.
double faceOnFraction(const glm::dvec3& cameraEcefMeters, const std::vector<glm::dvec3>& points,
                      const geo::Ellipsoid& ellipsoid);

// geometricError x viewportHeight / (2 x distance x tan(fovY / 2)): the error's size in pixels
// at the centre of the screen. distanceMeters is clamped to at least kMinimumDistanceMeters (NaN
// counts as that close); a geometric error of 0 gives 0.
double screenSpaceErrorPixels(double geometricErrorMeters, double distanceMeters,
                              const SelectionView& view);

// A lower bound of the distance from the camera to the nearest point of the region, >= 0
// (0 when the camera may be inside). The larger of two bounds: the camera's height above the
// region's highest point (everything at heights <= H > 0 lies inside the solid ellipsoid grown
// by H), and how far the volume's hull points (less the margin) lie beyond the camera along the
// direction to the volume's centre. cameraHeightMeters is the camera's geodetic height.
double distanceLowerBoundMeters(const glm::dvec3& cameraEcefMeters, double cameraHeightMeters,
                                const geo::RegionVolume& volume);

}  // namespace globe::terrain
