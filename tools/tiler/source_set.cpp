#include "tools/tiler/source_set.hpp"

#include <algorithm>
#include <cmath>

#include "geo/tiling_scheme.hpp"
#include "terrain/block_grid.hpp"
#include "terrain/height_block.hpp"

namespace globe::tiler {
namespace {

constexpr double kEdgeSnapDegrees = 1e-9;

}  // namespace

Result<int16_t> polarRowHeight(const io::RasterSource& raster, int64_t row) {
  const io::SampleGrid& grid = raster.grid();
  std::vector<int16_t> samples(static_cast<size_t>(grid.cols));
  if (auto read = raster.readRow(row, 0, grid.cols, samples.data()); !read)
    return Error{read.error()};
  std::optional<int16_t> highest;
  for (int16_t s : samples) {
    if (!terrain::isWater(s)) highest = std::max(highest.value_or(s), s);
  }
  if (highest) return *highest;
  // All water: the shallowest, so the pole is never below the water around it.
  return *std::max_element(samples.begin(), samples.end());
}

bool TilerSource::covers(double longitudeDegrees, double latitudeDegrees) const {
  if (latitudeDegrees < extent.south || latitudeDegrees > extent.north) return false;
  return grid.wrapsLongitude ||
         (longitudeDegrees >= extent.west && longitudeDegrees <= extent.east);
}

io::SourceInfo TilerSource::info() const {
  return {argument,    std::string(raster->formatName()), grid.cols, grid.rows, stepDegrees, extent,
          finestLevel, io::SourceConditioning{}};
}

uint32_t finestLevelForStep(double stepDegrees, uint32_t verticesPerSide) {
  for (uint32_t level = 0; level < geo::kMaxLevel; ++level) {
    // A hair of slack so a step equal to the spacing, printed with rounding, still matches.
    if (terrain::vertexSpacingDegrees(level, verticesPerSide) <= stepDegrees * (1.0 + 1e-9)) {
      return level;
    }
  }
  return geo::kMaxLevel;
}

Result<std::vector<TilerSource>> openSources(const std::vector<std::string>& inputs,
                                             const SourceSetOptions& options) {
  if (inputs.empty()) return makeError("no input rasters given");
  std::vector<TilerSource> sources;
  for (const std::string& input : inputs) {
    auto raster = io::openRasterSource(input);
    if (!raster) return Error{raster.error()};
    TilerSource source;
    source.grid = (*raster)->grid();
    source.raster = std::move(*raster);
    source.argument = input;
    const io::SampleGrid& g = source.grid;
    source.stepDegrees = std::min(g.columnStepDegrees, g.rowStepDegrees);
    source.finestLevel = finestLevelForStep(source.stepDegrees, options.verticesPerSide);
    if (options.maxLevel) source.finestLevel = std::min(source.finestLevel, *options.maxLevel);
    // Extents within rounding of the globe's edges are the edges: a raster whose cells reach
    // -89.99999999999999 covers the south pole.
    auto snapTo = [](double value, double edge) {
      return std::abs(value - edge) < kEdgeSnapDegrees ? edge : value;
    };
    source.extent = {
        snapTo(g.westDegrees(), -180.0), std::max(snapTo(g.southDegrees(), -90.0), -90.0),
        snapTo(g.eastDegrees(), 180.0), std::min(snapTo(g.northDegrees(), 90.0), 90.0)};
    if (g.wrapsLongitude) source.extent.west = -180.0, source.extent.east = 180.0;
    if (source.extent.west >= 180.0 || source.extent.east <= -180.0 ||
        source.extent.south >= 90.0 || source.extent.north <= -90.0) {
      return makeError(input + ": the raster lies outside longitude -180..180, latitude -90..90");
    }
    source.extent.west = std::max(source.extent.west, -180.0);
    source.extent.east = std::min(source.extent.east, 180.0);
    if (source.extent.north >= 90.0) {
      auto pole = polarRowHeight(*source.raster, 0);
      if (!pole) return Error{pole.error()};
      source.northPoleHeight = *pole;
    }
    if (source.extent.south <= -90.0) {
      auto pole = polarRowHeight(*source.raster, g.rows - 1);
      if (!pole) return Error{pole.error()};
      source.southPoleHeight = *pole;
    }
    sources.push_back(std::move(source));
  }
  std::stable_sort(sources.begin(), sources.end(), [](const TilerSource& a, const TilerSource& b) {
    return a.stepDegrees < b.stepDegrees;
  });
  return sources;
}

}  // namespace globe::tiler
