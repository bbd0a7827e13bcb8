#include "buildings/buildings_export.hpp"

#include <algorithm>
#include <filesystem>
#include <system_error>

#include "buildings/extrusion.hpp"
#include "buildings/glb_writer.hpp"
#include "buildings/tileset_writer.hpp"
#include "geo/cartographic.hpp"
#include "geo/ecef.hpp"
#include "surface/pyramid_surface.hpp"
#include "transport/atomic_file.hpp"

namespace globe::buildings {
namespace {

namespace fs = std::filesystem;

struct Placed {
  double baseMeters = 0, roofMeters = 0;
};

// The lowest ground at the outer ring's vertices and its centre.
Result<double> lowestGround(const Footprint& footprint, surface::PyramidSurface& surface) {
  const RingDegrees& outer = footprint.rings.front();
  glm::dvec2 sum(0.0);
  for (const glm::dvec2& p : outer) sum += p;
  std::vector<glm::dvec2> probes(outer.begin(), outer.end());
  probes.push_back(sum / static_cast<double>(outer.size()));
  double lowest = 1e300;
  for (const glm::dvec2& p : probes) {
    auto h = surface.heightMeters(geo::degreesToRadians(p.x), geo::degreesToRadians(p.y));
    if (!h) return Error{footprint.name + ": the pyramid's ground: " + h.error()};
    lowest = std::min(lowest, *h);
  }
  return lowest;
}

ExtentDegrees unionOf(const std::vector<ExtentDegrees>& extents) {
  ExtentDegrees u = extents.front();
  for (const ExtentDegrees& e : extents) {
    u = {std::min(u.west, e.west), std::min(u.south, e.south), std::max(u.east, e.east),
         std::max(u.north, e.north)};
  }
  return u;
}

// Writes one cell's GLB; returns its own buildings' bounds.
Result<CellBounds> writeCell(const QuadtreeCell& cell, const std::vector<Footprint>& footprints,
                             const std::vector<Placed>& placed,
                             const std::vector<ExtentDegrees>& extents, const fs::path& dir,
                             const geo::Ellipsoid& ellipsoid, BuildingsReport& report) {
  CellBounds own;
  BuildingMesh mesh;
  for (const size_t i : cell.items) {
    appendBuilding(footprints[i], placed[i].baseMeters, placed[i].roofMeters, ellipsoid, mesh);
    const CellBounds b{false, extents[i], placed[i].baseMeters, placed[i].roofMeters};
    own = own.empty ? b
                    : CellBounds{false,
                                 {std::min(own.extent.west, b.extent.west),
                                  std::min(own.extent.south, b.extent.south),
                                  std::max(own.extent.east, b.extent.east),
                                  std::max(own.extent.north, b.extent.north)},
                                 std::min(own.minHeightMeters, b.minHeightMeters),
                                 std::max(own.maxHeightMeters, b.maxHeightMeters)};
  }
  const double midLon = (own.extent.west + own.extent.east) / 2;
  const double midLat = (own.extent.south + own.extent.north) / 2;
  const glm::dvec3 centre = geo::cartographicToEcef(
      ellipsoid, geo::Cartographic::fromDegrees(midLon, midLat, own.minHeightMeters));
  const fs::path file = dir / contentUri(cell);
  std::error_code ec;
  fs::create_directories(file.parent_path(), ec);
  if (ec) return makeError(file.parent_path().string() + ": cannot create: " + ec.message());
  auto written = transport::writeFileAtomically(file, encodeGlb(mesh, centre));
  if (!written) return Error{written.error()};
  report.triangles += mesh.triangleCount();
  ++report.contents;
  return own;
}

}  // namespace

Result<BuildingsReport> exportBuildings(const BuildingsOptions& options,
                                        streaming::TerrainSource& pyramid,
                                        const geo::Ellipsoid& ellipsoid) {
  FootprintSet set;
  for (const std::string& input : options.inputs) {
    auto read = readFootprints(input, options.footprints, set);
    if (!read) return Error{read.error()};
  }
  BuildingsReport report;
  report.withoutHeight = set.withoutHeight, report.refused = set.refused;
  report.warnings = std::move(set.warnings), report.warningsDropped = set.warningsDropped;
  if (set.footprints.empty()) {
    return makeError("no footprint with a height in the inputs (" +
                     std::to_string(set.withoutHeight) + " without one, " +
                     std::to_string(set.refused) + " refused)");
  }
  surface::PyramidSurface surface(pyramid, ellipsoid);
  std::vector<Placed> placed;
  std::vector<ExtentDegrees> extents;
  for (const Footprint& f : set.footprints) {
    auto ground = lowestGround(f, surface);
    if (!ground) return Error{ground.error()};
    placed.push_back({*ground, *ground + f.heightMeters});
    extents.push_back(extentOf(f));
  }
  const std::vector<QuadtreeCell> cells =
      partitionBuildings(extents, unionOf(extents), options.quadtree);
  const fs::path dir = options.outputDir;
  std::vector<CellBounds> own(cells.size());
  for (size_t c = 0; c < cells.size(); ++c) {
    report.depth = std::max(report.depth, cells[c].level);
    if (cells[c].items.empty()) continue;
    auto bounds = writeCell(cells[c], set.footprints, placed, extents, dir, ellipsoid, report);
    if (!bounds) return Error{bounds.error()};
    own[c] = *bounds;
  }
  auto written = transport::writeFileAtomically(dir / "tileset.json", tilesetJson(cells, own));
  if (!written) return Error{written.error()};
  report.buildings = set.footprints.size();
  report.tiles = cells.size();
  report.lowestBaseMeters = 1e300, report.highestRoofMeters = -1e300;
  for (const Placed& p : placed) {
    report.lowestBaseMeters = std::min(report.lowestBaseMeters, p.baseMeters);
    report.highestRoofMeters = std::max(report.highestRoofMeters, p.roofMeters);
  }
  return report;
}

}  // namespace globe::buildings
