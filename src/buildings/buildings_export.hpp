// `globe-tiler buildings`: footprints (footprint_reader.hpp) stood on a pyramid's surface and
// written as a 3D Tiles 1.1 tileset. Each building's base is the lowest ground the pyramid gives
// at its outer ring's vertices and its centre, so it never floats where the ground falls away
// (its walls go into the ground where it rises); its roof is that base plus its height (OSM's
// `height` is the roof above the ground: taken from the lowest ground, a building on a slope
// keeps its height on its downhill side). Every file goes to a temporary name, then is renamed;
// tileset.json last.
#pragma once

#include <string>
#include <vector>

#include "buildings/building_quadtree.hpp"
#include "buildings/footprint_reader.hpp"
#include "core/result.hpp"
#include "geo/ellipsoid.hpp"
#include "streaming/terrain_source.hpp"

namespace globe::buildings {

struct BuildingsOptions {
  std::vector<std::string> inputs;  // vector files of footprints
  std::string outputDir;            // the tileset's folder (created)
  FootprintOptions footprints;
  QuadtreeLimits quadtree;
};

struct BuildingsReport {
  size_t buildings = 0;      // footprints extruded (each part of a multi-polygon one)
  size_t withoutHeight = 0;  // features skipped: no height attribute of any kind
  size_t refused = 0;        // features skipped: a bad height or geometry (warnings name them)
  size_t tiles = 0, contents = 0, triangles = 0;
  uint32_t depth = 0;  // the quadtree's deepest level
  double lowestBaseMeters = 0, highestRoofMeters = 0;
  std::vector<std::string> warnings;
  size_t warningsDropped = 0;  // warnings past FootprintLimits::maxWarnings, only counted
};

// Errors: inputs that cannot be read (footprint_reader.hpp), no footprint with a height in any,
// unreadable packs of the pyramid, files that cannot be written; each names the file.
Result<BuildingsReport> exportBuildings(const BuildingsOptions& options,
                                        streaming::TerrainSource& pyramid,
                                        const geo::Ellipsoid& ellipsoid);

}  // namespace globe::buildings
