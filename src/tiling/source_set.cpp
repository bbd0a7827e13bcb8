#include "tiling/source_set.hpp"

#include <algorithm>
#include <cmath>

#include "geo/tiling_scheme.hpp"
#include "terrain/block_grid.hpp"
#include "terrain/height_block.hpp"

namespace globe::tiling {
namespace {

constexpr double kEdgeSnapDegrees = 1e-9;

}  // namespace

Result<int16_t> polarRowHeight(const rasters::RasterSource& raster, int64_t row) {
  const geo::SampleGrid& grid = raster.grid();
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

formats::SourceInfo TilerSource::info() const {
  formats::SourceInfo info;
  info.path = argument;
  info.format = format;
  info.columns = grid.cols;
  info.rows = grid.rows;
  info.stepDegrees = stepDegrees;
  info.bounds = extent;
  info.finestLevel = finestLevel;
  info.verticalUnits = verticalUnits;
  return info;
}

Result<void> checkValidSamples(const rasters::RasterSource& raster, bool noDataIsWater) {
  const geo::SampleGrid& g = raster.grid();
  const auto refuse = [&](const std::string& why) {
    return makeError(raster.path() + ": fewer than 2x2 valid samples (" + why +
                     "); nothing to tile");
  };
  if (g.cols < 2 || g.rows < 2) {
    return refuse("the raster is " + std::to_string(g.cols) + "x" + std::to_string(g.rows));
  }
  if (noDataIsWater) return {};  // its no data is sea: every sample says something
  std::vector<int16_t> samples(static_cast<size_t>(g.cols));
  int64_t valid = 0, rowsWithValid = 0;
  int64_t westmost = g.cols, eastmost = -1;  // columns of the valid samples seen
  for (int64_t row = 0; row < g.rows; ++row) {
    if (auto read = raster.readRow(row, 0, g.cols, samples.data()); !read) return read;
    bool rowHasValid = false;
    for (int64_t column = 0; column < g.cols; ++column) {
      if (samples[static_cast<size_t>(column)] == terrain::kNoDataHeight) continue;
      ++valid;
      rowHasValid = true;
      westmost = std::min(westmost, column);
      eastmost = std::max(eastmost, column);
    }
    rowsWithValid += rowHasValid ? 1 : 0;
    if (valid >= 4 && rowsWithValid >= 2 && eastmost > westmost) return {};
  }
  if (valid == 0) return refuse("every sample is no data");
  return refuse(std::to_string(valid) + " valid, in " + std::to_string(rowsWithValid) +
                (rowsWithValid == 1 ? " row" : " rows") + " and " +
                (eastmost > westmost ? "several columns" : "one column"));
}

bool noDataIsOceanMask(const rasters::RasterSource& raster) {
  constexpr double kThirtySecondsDegrees = 1.0 / 120.0;
  const geo::SampleGrid& g = raster.grid();
  auto isThirtySeconds = [&](double step) {
    return std::abs(step - kThirtySecondsDegrees) < 1e-9 * kThirtySecondsDegrees;
  };
  return raster.formatName() == "GTOPO30" && isThirtySeconds(g.columnStepDegrees) &&
         isThirtySeconds(g.rowStepDegrees);
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

Result<void> openRaster(TilerSource& source) {
  if (source.raster) return {};
  auto raster = rasters::openRasterSource(source.argument, source.openOptions);
  if (!raster) return Error{raster.error()};
  const geo::SampleGrid& now = (*raster)->grid();
  const geo::SampleGrid& was = source.grid;
  if (now.cols != was.cols || now.rows != was.rows ||
      now.columnStepDegrees != was.columnStepDegrees || now.rowStepDegrees != was.rowStepDegrees ||
      now.firstColumnLongitudeDegrees != was.firstColumnLongitudeDegrees ||
      now.firstRowLatitudeDegrees != was.firstRowLatitudeDegrees) {
    return makeError(source.argument + ": the raster changed while it was being tiled");
  }
  source.raster = std::move(*raster);
  return {};
}

Result<std::vector<TilerSource>> openSources(const std::vector<std::string>& inputs,
                                             const SourceSetOptions& options) {
  if (inputs.empty()) return makeError("no input rasters given");
  if (auto checked = formats::checkVerticalOverride(options.vertical); !checked) {
    return Error{checked.error()};
  }
  std::vector<TilerSource> sources;
  for (const std::string& input : inputs) {
    const rasters::RasterOpenOptions openOptions{options.vertical, options.allowImages};
    auto raster = rasters::openRasterSource(input, openOptions);
    if (!raster) return Error{raster.error()};
    TilerSource source;
    source.openOptions = openOptions;
    source.rasterPath = (*raster)->path();
    source.format = std::string((*raster)->formatName());
    source.noDataIsWater = options.noDataIsSea || noDataIsOceanMask(**raster);
    if (auto enough = checkValidSamples(**raster, source.noDataIsWater); !enough) {
      return Error{enough.error()};
    }
    source.verticalUnits = (*raster)->verticalUnits();
    source.grid = (*raster)->grid();
    source.raster = std::move(*raster);
    source.argument = input;
    const geo::SampleGrid& g = source.grid;
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
    source.raster.reset();
    sources.push_back(std::move(source));
  }
  std::stable_sort(sources.begin(), sources.end(), [](const TilerSource& a, const TilerSource& b) {
    return a.stepDegrees < b.stepDegrees;
  });
  return sources;
}

}  // namespace globe::tiling
