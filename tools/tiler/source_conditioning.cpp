#include "tools/tiler/source_conditioning.hpp"

#include <algorithm>
#include <memory>

#include "dem/condition.hpp"
#include "dem/grid_coarser_sources.hpp"

namespace globe::tiler {
namespace {

constexpr double kSameStepTolerance = 1e-6;

// A conditioned source in memory, read like the original.
class ConditionedRaster final : public io::RasterSource {
 public:
  ConditionedRaster(std::unique_ptr<io::RasterSource> original, std::shared_ptr<dem::DemGrid> grid)
      : original_(std::move(original)), grid_(std::move(grid)) {}
  const std::string& path() const override { return original_->path(); }
  std::string_view formatName() const override { return original_->formatName(); }
  const io::SampleGrid& grid() const override { return original_->grid(); }
  Result<void> readRow(int64_t row, int64_t firstColumn, int64_t count,
                       int16_t* out) const override {
    const io::SampleGrid& g = original_->grid();
    if (row < 0 || row >= g.rows || count < 0 ||
        (!g.wrapsLongitude && (firstColumn < 0 || firstColumn + count > g.cols))) {
      return makeError(path() + ": row " + std::to_string(row) + " columns " +
                       std::to_string(firstColumn) + "+" + std::to_string(count) +
                       " outside the raster");
    }
    for (int64_t k = 0; k < count; ++k) {
      int64_t column = (firstColumn + k) % g.cols;
      if (column < 0) column += g.cols;
      out[k] = grid_->at(row, column);
    }
    return {};
  }

 private:
  std::unique_ptr<io::RasterSource> original_;
  std::shared_ptr<dem::DemGrid> grid_;
};

Result<std::shared_ptr<dem::DemGrid>> readWhole(const TilerSource& source) {
  const io::SampleGrid& g = source.grid;
  auto grid = std::make_shared<dem::DemGrid>();
  grid->cols = g.cols;
  grid->rows = g.rows;
  grid->firstColumnLongitudeDegrees = g.firstColumnLongitudeDegrees;
  grid->firstRowLatitudeDegrees = g.firstRowLatitudeDegrees;
  grid->columnStepDegrees = g.columnStepDegrees;
  grid->rowStepDegrees = g.rowStepDegrees;
  grid->wrapsLongitude = g.wrapsLongitude;
  grid->samples.resize(static_cast<size_t>(g.cols) * static_cast<size_t>(g.rows));
  for (int64_t row = 0; row < g.rows; ++row) {
    if (auto read =
            source.raster->readRow(row, 0, g.cols, grid->samples.data() + grid->index(row, 0));
        !read) {
      return Error{read.error()};
    }
  }
  return grid;
}

bool extentsMeet(const io::BoundsDegrees& a, const io::BoundsDegrees& b) {
  return a.west <= b.east && b.west <= a.east && a.south <= b.north && b.south <= a.north;
}

}  // namespace

Result<std::vector<io::SourceConditioning>> conditionSources(std::vector<TilerSource>& sources) {
  std::vector<std::shared_ptr<dem::DemGrid>> grids(sources.size());
  std::vector<io::SourceConditioning> report(sources.size());
  // Coarsest first: a source is conditioned against coarser ones that already are.
  for (size_t i = sources.size(); i-- > 0;) {
    const TilerSource& source = sources[i];
    auto grid = readWhole(source);
    if (!grid) return Error{grid.error()};

    std::vector<const dem::DemGrid*> coarser;  // finest first
    double nextCoarserStep = 0;
    for (size_t j = i + 1; j < sources.size(); ++j) {
      if (sources[j].stepDegrees <= source.stepDegrees * (1 + kSameStepTolerance)) continue;
      if (!sources[j].grid.wrapsLongitude && !source.grid.wrapsLongitude &&
          !extentsMeet(sources[j].extent, source.extent)) {
        continue;
      }
      if (coarser.empty()) nextCoarserStep = sources[j].stepDegrees;
      coarser.push_back(grids[j].get());
    }
    const dem::GridCoarserSources coarserSources(coarser);

    dem::ConditionOptions options;
    if (!coarser.empty()) {
      const double side = std::min(source.extent.east - source.extent.west,
                                   source.extent.north - source.extent.south);
      options.blendMarginDegrees =
          std::min(kBlendMarginCoarserCells * nextCoarserStep, kBlendMarginMaximumFraction * side);
    }
    options.sameOrFinerCovers = [&sources, i](double longitude, double latitude) {
      for (size_t j = 0; j < sources.size(); ++j) {
        if (j == i) continue;
        if (sources[j].stepDegrees > sources[i].stepDegrees * (1 + kSameStepTolerance)) break;
        if (sources[j].covers(longitude, latitude)) return true;
      }
      return false;
    };
    const dem::ConditionStats stats =
        dem::conditionGrid(**grid, coarser.empty() ? nullptr : &coarserSources, options);
    report[i] = {stats.noDataSamples,
                 stats.seaSamples,
                 stats.voidSamples,
                 stats.fill.interpolatedSamples,
                 stats.fill.fromCoarserSamples,
                 stats.fill.unfilledSamples,
                 stats.blendedSamples,
                 options.blendMarginDegrees};
    grids[i] = *grid;
  }
  for (size_t i = 0; i < sources.size(); ++i) {
    sources[i].raster = std::make_unique<ConditionedRaster>(std::move(sources[i].raster), grids[i]);
    // The poles' one value, from the conditioned polar rows.
    if (sources[i].northPoleHeight) {
      auto pole = polarRowHeight(*sources[i].raster, 0);
      if (!pole) return Error{pole.error()};
      sources[i].northPoleHeight = *pole;
    }
    if (sources[i].southPoleHeight) {
      auto pole = polarRowHeight(*sources[i].raster, sources[i].grid.rows - 1);
      if (!pole) return Error{pole.error()};
      sources[i].southPoleHeight = *pole;
    }
  }
  return report;
}

}  // namespace globe::tiler
