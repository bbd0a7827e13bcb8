#include "tiling/source_sampler.hpp"

#include <algorithm>
#include <cmath>

#include "conditioning/footprint_bend.hpp"
#include "conditioning/vertex_sample.hpp"
#include "terrain/height_block.hpp"

namespace globe::tiling {
namespace {

int64_t floorToInt(double value) { return static_cast<int64_t>(std::floor(value)); }

int64_t wrapColumn(int64_t column, int64_t columns) {
  const int64_t wrapped = column % columns;
  return wrapped < 0 ? wrapped + columns : wrapped;
}

// Fractional column of a longitude, clamped (or wrapped) into the grid.
double columnOf(const geo::SampleGrid& grid, double longitudeDegrees) {
  double offset = longitudeDegrees - grid.firstColumnLongitudeDegrees;
  if (grid.wrapsLongitude) {
    offset -= 360.0 * std::floor(offset / 360.0);
    return offset / grid.columnStepDegrees;
  }
  return std::clamp(offset / grid.columnStepDegrees, 0.0, static_cast<double>(grid.cols - 1));
}

double rowOf(const geo::SampleGrid& grid, double latitudeDegrees) {
  const double offset = grid.firstRowLatitudeDegrees - latitudeDegrees;
  return std::clamp(offset / grid.rowStepDegrees, 0.0, static_cast<double>(grid.rows - 1));
}

// Whether the point lies between the grid's first and last sample centres (not in the half-cell
// rim its cells reach beyond them, where its samples can only be clamped).
bool betweenSampleCentres(const geo::SampleGrid& grid, double longitudeDegrees,
                          double latitudeDegrees) {
  const double row = (grid.firstRowLatitudeDegrees - latitudeDegrees) / grid.rowStepDegrees;
  if (row < 0 || row > static_cast<double>(grid.rows - 1)) return false;
  if (grid.wrapsLongitude) return true;
  const double column =
      (longitudeDegrees - grid.firstColumnLongitudeDegrees) / grid.columnStepDegrees;
  return column >= 0 && column <= static_cast<double>(grid.cols - 1);
}

// The finer source's edge as the ground outside it bends to (src/tiling/edge_profile.hpp): at
// distance d beyond a side, that side's heights averaged over d each way along it; beyond a
// corner, both sides' averages mixed by how far the point lies beyond each.
double edgeHeightMeters(const TilerSource& finer, double longitudeDegrees, double latitudeDegrees) {
  const geo::SampleGrid& grid = finer.grid;
  const formats::BoundsDegrees& e = finer.extent;
  const double dx = std::max({e.west - longitudeDegrees, 0.0, longitudeDegrees - e.east});
  const double dy = std::max({e.south - latitudeDegrees, 0.0, latitudeDegrees - e.north});
  const double distance = std::hypot(dx, dy);
  const double column =
      (longitudeDegrees - grid.firstColumnLongitudeDegrees) / grid.columnStepDegrees;
  const double row = (grid.firstRowLatitudeDegrees - latitudeDegrees) / grid.rowStepDegrees;
  const EdgeProfiles& edges = *finer.edges;
  const double beside = (longitudeDegrees < e.west ? edges.west : edges.east)
                            .meanMeters(row, distance / grid.rowStepDegrees);
  const double beyond = (latitudeDegrees > e.north ? edges.north : edges.south)
                            .meanMeters(column, distance / grid.columnStepDegrees);
  if (dx <= 0) return beyond;
  if (dy <= 0) return beside;
  return (dx * beside + dy * beyond) / (dx + dy);
}

}  // namespace

double bendWeightOutside(const TilerSource& finer, double longitudeDegrees,
                         double latitudeDegrees) {
  const formats::BoundsDegrees& e = finer.extent;
  const double dx = std::max({e.west - longitudeDegrees, 0.0, longitudeDegrees - e.east});
  const double dy = std::max({e.south - latitudeDegrees, 0.0, latitudeDegrees - e.north});
  const double outside = std::hypot(dx, dy);
  if (outside <= 0) return 0.0;
  return conditioning::bendWeight(outside, finer.bendMarginDegrees);
}

SourceSampler::SourceSampler(const std::vector<TilerSource>& sources, uint32_t maxFinestLevel,
                             double stripWestDegrees, double stripEastDegrees) {
  for (const TilerSource& source : sources) {
    // A source finer than this level still shapes the ground around its edges (the bend).
    const bool bendOnly = source.finestLevel > maxFinestLevel;
    if (bendOnly && !(source.bendMarginDegrees > 0)) continue;
    const double reach = source.bendMarginDegrees;
    const geo::SampleGrid& grid = source.grid;
    if (!grid.wrapsLongitude && (source.extent.east + reach < stripWestDegrees ||
                                 source.extent.west - reach > stripEastDegrees)) {
      continue;
    }
    // Columns needed for every longitude of the strip, one sample of margin each side.
    const int64_t first = floorToInt(columnOf(grid, stripWestDegrees)) - 1;
    const double spanColumns = (stripEastDegrees - stripWestDegrees) / grid.columnStepDegrees;
    int64_t count = static_cast<int64_t>(std::ceil(spanColumns)) + 3;
    Candidate candidate{&source, 0, grid.cols, bendOnly};
    if (grid.wrapsLongitude) {
      if (count < grid.cols) candidate = {&source, wrapColumn(first, grid.cols), count, bendOnly};
    } else {
      const int64_t begin = std::clamp<int64_t>(first, 0, grid.cols - 1);
      const int64_t end = std::clamp<int64_t>(first + count, begin + 1, grid.cols);
      candidate = {&source, begin, end - begin, bendOnly};
    }
    // Sources whose edges shape the ground around them (the bend), listed once per strip.
    if (source.bendMarginDegrees > 0 && !grid.wrapsLongitude) {
      bendCandidates_.push_back(candidates_.size());
    }
    candidates_.push_back(candidate);
  }
}

Result<const std::vector<int16_t>*> SourceSampler::row(size_t candidateIndex, int64_t rowIndex) {
  auto [it, inserted] = rows_.try_emplace({candidateIndex, rowIndex});
  if (inserted) {
    const Candidate& c = candidates_[candidateIndex];
    it->second.samples.resize(static_cast<size_t>(c.columnCount));
    auto read = c.source->raster->readRow(rowIndex, c.firstColumn, c.columnCount,
                                          it->second.samples.data());
    if (!read) {
      rows_.erase(it);
      return Error{read.error()};
    }
    ++rowReads_;
  }
  return &it->second.samples;
}

int16_t SourceSampler::at(const Candidate& c, const std::vector<int16_t>& rowSamples,
                          int64_t column) const {
  int64_t offset = column - c.firstColumn;
  if (c.source->grid.wrapsLongitude) {
    offset = wrapColumn(column, c.source->grid.cols) - c.firstColumn;
    if (offset < 0) offset += c.source->grid.cols;
  }
  return rowSamples[static_cast<size_t>(std::clamp<int64_t>(offset, 0, c.columnCount - 1))];
}

Result<int16_t> SourceSampler::sampleSource(const Candidate& c, double longitudeDegrees,
                                            double latitudeDegrees) {
  const TilerSource& source = *c.source;
  if (latitudeDegrees >= 90.0 && source.northPoleHeight) return *source.northPoleHeight;
  if (latitudeDegrees <= -90.0 && source.southPoleHeight) return *source.southPoleHeight;
  const geo::SampleGrid& grid = source.grid;
  const double u = columnOf(grid, longitudeDegrees);
  const double v = rowOf(grid, latitudeDegrees);
  const int64_t column0 = floorToInt(u);
  const int64_t row0 = floorToInt(v);
  const int64_t column1 = grid.wrapsLongitude ? column0 + 1 : std::min(column0 + 1, grid.cols - 1);
  const int64_t row1 = std::min(row0 + 1, grid.rows - 1);
  const double tu = u - static_cast<double>(column0);
  const double tv = v - static_cast<double>(row0);

  const size_t index = static_cast<size_t>(&c - candidates_.data());
  auto top = row(index, row0);
  if (!top) return Error{top.error()};
  auto bottom = row(index, row1);
  if (!bottom) return Error{bottom.error()};
  const int16_t s00 = at(c, **top, column0), s01 = at(c, **top, column1);
  const int16_t s10 = at(c, **bottom, column0), s11 = at(c, **bottom, column1);

  return conditioning::interpolateSample({s00, s01, s10, s11}, tu, tv);
}

Result<int16_t> SourceSampler::sample(double longitudeDegrees, double latitudeDegrees) {
  // The finest covering source wins; among equally fine ones, one whose samples surround the
  // point beats one that reaches it only with its rim (two adjacent SRTM tiles: each is drawn
  // from its own samples up to the shared line).
  const Candidate* chosen = nullptr;
  for (const Candidate& c : candidates_) {
    if (c.bendOnly || !c.source->covers(longitudeDegrees, latitudeDegrees)) continue;
    if (chosen != nullptr && c.source->stepDegrees > chosen->source->stepDegrees * (1 + 1e-6)) {
      break;
    }
    if (chosen == nullptr) chosen = &c;
    if (betweenSampleCentres(c.source->grid, longitudeDegrees, latitudeDegrees)) {
      chosen = &c;
      break;
    }
  }
  if (chosen == nullptr) return terrain::kNoDataHeight;
  auto value = sampleSource(*chosen, longitudeDegrees, latitudeDegrees);
  if (!value) return value;

  // Just outside a finer source the coarser surface bends to meet that source's edge (a shore
  // where one side is water), so the two meet without a wall or a moat at the edge.
  const Candidate* nearest = nullptr;
  double weight = 0;
  for (size_t index : bendCandidates_) {
    const Candidate& c = candidates_[index];
    if (!(c.source->stepDegrees < chosen->source->stepDegrees)) continue;
    const double w = bendWeightOutside(*c.source, longitudeDegrees, latitudeDegrees);
    if (w > weight) weight = w, nearest = &c;
  }
  if (nearest == nullptr || !nearest->source->edges) return value;
  const double edgeMeters = edgeHeightMeters(*nearest->source, longitudeDegrees, latitudeDegrees);
  return conditioning::bentSample(*value, weight * (edgeMeters - terrain::seaFloorMeters(*value)));
}

}  // namespace globe::tiling
