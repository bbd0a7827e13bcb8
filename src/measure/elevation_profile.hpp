// An elevation profile: a path sampled at least at the terrain's resolution along its geodesics,
// each sample's height from the pyramid's exact surface (globe query --mode exact's), the slope
// between samples, and the file's own elevations beside them (a GPX track's <ele>).
#pragma once

#include <cstddef>
#include <vector>

#include "core/result.hpp"
#include "geo/ellipsoid.hpp"
#include "measure/geodesic_path.hpp"
#include "streaming/terrain_source.hpp"

namespace globe::measure {

struct ProfileRow {
  PathSample sample;
  double heightMeters = 0;  // the exact surface (0 m where the pyramid has nothing)
  double slopeDegrees = 0;  // to the next sample (the last: from the previous)
};

struct ProfileOptions {
  double maxSpacingMeters = 0;    // 0: the pyramid's finest vertex spacing along the path
  size_t maxSamples = 2'000'000;  // more is an error naming the path's length
};

// The finest vertex spacing of the pyramid, metres, at the path's highest latitude (east-west
// spacing shrinks towards the poles; capped at 80 degrees).
double terrainSpacingMeters(const streaming::TerrainSource& source,
                            const std::vector<PathPoint>& path);

Result<std::vector<ProfileRow>> elevationProfile(streaming::TerrainSource& source,
                                                 const std::vector<PathPoint>& path,
                                                 const geo::Ellipsoid& ellipsoid,
                                                 const ProfileOptions& options = {});

}  // namespace globe::measure
