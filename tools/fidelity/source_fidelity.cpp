#include "tools/fidelity/source_fidelity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "terrain/block_grid.hpp"
#include "terrain/height_block.hpp"

namespace globe::fidelity {
namespace {

constexpr int16_t kNoData = terrain::kNoDataHeight;
constexpr int32_t kAbsent = std::numeric_limits<int32_t>::min();

// The drawn vertices of one level over a window, by global vertex row and column.
struct Lattice {
  double spacingDegrees = 0;
  int64_t firstRow = 0, firstColumn = 0, rows = 0, columns = 0;
  std::vector<int32_t> samples;  // kAbsent where no tile was drawn
  int32_t at(int64_t row, int64_t column) const {
    if (row < firstRow || row >= firstRow + rows || column < firstColumn ||
        column >= firstColumn + columns)
      return kAbsent;
    return samples[static_cast<size_t>((row - firstRow) * columns + (column - firstColumn))];
  }
  double longitude(int64_t column) const {
    return -180.0 + spacingDegrees * static_cast<double>(column);
  }
  double latitude(int64_t row) const { return 90.0 - spacingDegrees * static_cast<double>(row); }
};

Result<Lattice> readLattice(streaming::TileStore& store, uint32_t level, double west, double south,
                            double east, double north) {
  const uint32_t n = store.manifest().verticesPerSide;
  const double tileDegrees = 180.0 / static_cast<double>(uint64_t{1} << level);
  const auto tilesX = int64_t{2} << level, tilesY = int64_t{1} << level;
  const int64_t x0 = std::clamp<int64_t>(
      static_cast<int64_t>(std::floor((west + 180.0) / tileDegrees)), 0, tilesX - 1);
  const int64_t x1 = std::clamp<int64_t>(
      static_cast<int64_t>(std::floor((east + 180.0) / tileDegrees)), 0, tilesX - 1);
  const int64_t y0 = std::clamp<int64_t>(
      static_cast<int64_t>(std::floor((90.0 - north) / tileDegrees)), 0, tilesY - 1);
  const int64_t y1 = std::clamp<int64_t>(
      static_cast<int64_t>(std::floor((90.0 - south) / tileDegrees)), 0, tilesY - 1);
  Lattice lattice;
  lattice.spacingDegrees = terrain::vertexSpacingDegrees(level, n);
  const int64_t side = n - 1;
  lattice.firstRow = y0 * side, lattice.firstColumn = x0 * side;
  lattice.rows = (y1 - y0 + 1) * side + 1, lattice.columns = (x1 - x0 + 1) * side + 1;
  lattice.samples.assign(static_cast<size_t>(lattice.rows * lattice.columns), kAbsent);
  for (int64_t y = y0; y <= y1; ++y) {
    for (int64_t x = x0; x <= x1; ++x) {
      const geo::TileId tile{level, static_cast<uint32_t>(x), static_cast<uint32_t>(y)};
      auto loaded = store.load(tile);
      if (!loaded) return Error{loaded.error()};
      if (!*loaded) continue;  // no tile there
      const terrain::HeightBlock& block = **loaded;
      for (uint32_t i = 0; i < n; ++i) {
        for (uint32_t j = 0; j < n; ++j) {
          const int64_t row = y * side + i - lattice.firstRow;
          const int64_t column = x * side + j - lattice.firstColumn;
          lattice.samples[static_cast<size_t>(row * lattice.columns + column)] = block.at(i, j);
        }
      }
    }
  }
  return lattice;
}

// No-data samples reaching the grid's border through no data (8 neighbours): off the footprint.
std::vector<uint8_t> noDataReachingBorder(const conditioning::DemGrid& grid) {
  std::vector<uint8_t> reached(grid.samples.size(), 0);
  std::vector<size_t> stack;
  auto push = [&](int64_t r, int64_t c) {
    const size_t i = grid.index(r, c);
    if (grid.samples[i] == kNoData && reached[i] == 0) reached[i] = 1, stack.push_back(i);
  };
  for (int64_t c = 0; c < grid.cols; ++c) push(0, c), push(grid.rows - 1, c);
  for (int64_t r = 0; r < grid.rows; ++r) push(r, 0), push(r, grid.cols - 1);
  while (!stack.empty()) {
    const size_t i = stack.back();
    stack.pop_back();
    const auto r = static_cast<int64_t>(i / static_cast<size_t>(grid.cols));
    const auto c = static_cast<int64_t>(i % static_cast<size_t>(grid.cols));
    for (int64_t dr = -1; dr <= 1; ++dr) {
      for (int64_t dc = -1; dc <= 1; ++dc) {
        if (r + dr >= 0 && r + dr < grid.rows && c + dc >= 0 && c + dc < grid.cols) {
          push(r + dr, c + dc);
        }
      }
    }
  }
  return reached;
}

// A coarser source's surface as given: bilinear over its samples, sea floors where measured, its
// no data (GTOPO30's sea) at 0 m. Nullopt beyond its cells.
std::optional<double> coarseSurfaceMeters(const conditioning::DemGrid& grid, double lon,
                                          double lat) {
  const double halfColumn = grid.columnStepDegrees / 2, halfRow = grid.rowStepDegrees / 2;
  if (lat > grid.firstRowLatitudeDegrees + halfRow ||
      lat < grid.latitudeDegrees(grid.rows - 1) - halfRow)
    return std::nullopt;
  double u = (lon - grid.firstColumnLongitudeDegrees) / grid.columnStepDegrees;
  if (grid.wrapsLongitude) {
    u -= static_cast<double>(grid.cols) * std::floor(u / static_cast<double>(grid.cols));
  } else if (lon < grid.firstColumnLongitudeDegrees - halfColumn ||
             lon > grid.longitudeDegrees(grid.cols - 1) + halfColumn) {
    return std::nullopt;
  } else {
    u = std::clamp(u, 0.0, static_cast<double>(grid.cols - 1));
  }
  const double v = std::clamp((grid.firstRowLatitudeDegrees - lat) / grid.rowStepDegrees, 0.0,
                              static_cast<double>(grid.rows - 1));
  const auto c0 = static_cast<int64_t>(std::floor(u)), r0 = static_cast<int64_t>(std::floor(v));
  const int64_t c1 = grid.wrapsLongitude ? (c0 + 1) % grid.cols : std::min(c0 + 1, grid.cols - 1);
  const int64_t r1 = std::min(r0 + 1, grid.rows - 1);
  const double tu = u - static_cast<double>(c0), tv = v - static_cast<double>(r0);
  auto h = [&](int64_t r, int64_t c) {
    const int16_t sample = grid.at(r, c);
    return sample == kNoData ? 0.0 : static_cast<double>(sample);
  };
  return (1 - tv) * ((1 - tu) * h(r0, c0) + tu * h(r0, c1)) +
         tv * ((1 - tu) * h(r1, c0) + tu * h(r1, c1));
}

bool betweenSampleCentres(const conditioning::DemGrid& grid, double lon, double lat) {
  const double column = (lon - grid.firstColumnLongitudeDegrees) / grid.columnStepDegrees;
  const double row = (grid.firstRowLatitudeDegrees - lat) / grid.rowStepDegrees;
  return column >= 0 && column <= static_cast<double>(grid.cols - 1) && row >= 0 &&
         row <= static_cast<double>(grid.rows - 1);
}

// The largest step between the source's own neighbouring data samples within `radius` samples
// of (row, column).
double largestSourceStep(const conditioning::DemGrid& grid, int64_t row, int64_t column,
                         int64_t radius) {
  double largest = 0;
  for (int64_t r = std::max<int64_t>(0, row - radius); r <= std::min(grid.rows - 1, row + radius);
       ++r) {
    for (int64_t c = std::max<int64_t>(0, column - radius);
         c <= std::min(grid.cols - 1, column + radius); ++c) {
      const int16_t here = grid.at(r, c);
      if (here == kNoData) continue;
      if (c + 1 < grid.cols && grid.at(r, c + 1) != kNoData) {
        largest = std::max(largest, std::abs(double(here) - double(grid.at(r, c + 1))));
      }
      if (r + 1 < grid.rows && grid.at(r + 1, c) != kNoData) {
        largest = std::max(largest, std::abs(double(here) - double(grid.at(r + 1, c))));
      }
    }
  }
  return largest;
}

DifferenceStats summarise(std::vector<double> differences) {
  DifferenceStats stats;
  stats.count = differences.size();
  if (differences.empty()) return stats;
  const auto k = static_cast<std::ptrdiff_t>(static_cast<double>(differences.size() - 1) * 0.95);
  std::nth_element(differences.begin(), differences.begin() + k, differences.end());
  stats.p95Meters = differences[static_cast<size_t>(k)];
  stats.maxMeters = *std::max_element(differences.begin(), differences.end());
  return stats;
}

}  // namespace

Result<SourceFidelity> measureSourceFidelity(
    streaming::TileStore& store, uint32_t level, const conditioning::DemGrid& source,
    const std::vector<const conditioning::DemGrid*>& coarser,
    const std::vector<const conditioning::DemGrid*>& peers, bool noDataIsWater,
    double edgeBandDegrees) {
  const double west = source.longitudeDegrees(0) - source.columnStepDegrees / 2;
  const double east = source.longitudeDegrees(source.cols - 1) + source.columnStepDegrees / 2;
  const double north = source.latitudeDegrees(0) + source.rowStepDegrees / 2;
  const double south = source.latitudeDegrees(source.rows - 1) - source.rowStepDegrees / 2;
  const double pad = 0.02;
  auto read = readLattice(store, level, west - pad, south - pad, east + pad, north + pad);
  if (!read) return Error{read.error()};
  const Lattice& lattice = *read;
  const std::vector<uint8_t> offData = noDataReachingBorder(source);

  // Per lattice vertex: 1 on the footprint (2×2 data samples), 2 off it (beyond the outer
  // sample centres, or a sample of the 2×2 is no data reaching the border), 0 neither (beside an
  // enclosed void); and the source's bilinear value where on it.
  const size_t count = lattice.samples.size();
  std::vector<uint8_t> where(count, 0);
  std::vector<double> sourceMeters(count, 0);
  // Land: the 2×2 samples all measured above 0 m (a coast's vertices follow the coast rule of
  // conditioning/vertex_sample.hpp instead). Over no data: the nearest sample is no data and none
  // of the four is a measured sample at or below 0 m.
  std::vector<uint8_t> land(count, 0), overNoData(count, 0);
  auto indexOf = [&](int64_t row, int64_t column) {
    return static_cast<size_t>((row - lattice.firstRow) * lattice.columns +
                               (column - lattice.firstColumn));
  };
  for (int64_t row = lattice.firstRow; row < lattice.firstRow + lattice.rows; ++row) {
    const double lat = lattice.latitude(row);
    for (int64_t column = lattice.firstColumn; column < lattice.firstColumn + lattice.columns;
         ++column) {
      const double lon = lattice.longitude(column);
      const size_t k = indexOf(row, column);
      if (lattice.samples[k] == kAbsent) continue;
      // Beyond the rectangle, or in the half-cell rim beyond the outer sample centres (there a
      // neighbouring source, or the clamped edge sample, is drawn): off the footprint.
      const double columnAt = (lon - source.firstColumnLongitudeDegrees) / source.columnStepDegrees;
      const double rowAt = (source.firstRowLatitudeDegrees - lat) / source.rowStepDegrees;
      if (columnAt < 0 || columnAt > static_cast<double>(source.cols - 1) || rowAt < 0 ||
          rowAt > static_cast<double>(source.rows - 1)) {
        // Where an equally fine source goes on, the two join as they are: not an edge.
        const bool peerGoesOn = std::any_of(
            peers.begin(), peers.end(),
            [&](const conditioning::DemGrid* p) { return betweenSampleCentres(*p, lon, lat); });
        where[k] = peerGoesOn ? 0 : 2;
        continue;
      }
      const double u =
          std::clamp((lon - source.firstColumnLongitudeDegrees) / source.columnStepDegrees, 0.0,
                     static_cast<double>(source.cols - 1));
      const double v = std::clamp((source.firstRowLatitudeDegrees - lat) / source.rowStepDegrees,
                                  0.0, static_cast<double>(source.rows - 1));
      const auto c0 = static_cast<int64_t>(std::floor(u)), r0 = static_cast<int64_t>(std::floor(v));
      const int64_t c1 = std::min(c0 + 1, source.cols - 1), r1 = std::min(r0 + 1, source.rows - 1);
      const double tu = u - static_cast<double>(c0), tv = v - static_cast<double>(r0);
      const int16_t s[4] = {source.at(r0, c0), source.at(r0, c1), source.at(r1, c0),
                            source.at(r1, c1)};
      const int16_t nearest = source.at(std::lround(v), std::lround(u));
      if (std::none_of(std::begin(s), std::end(s), [](int16_t x) { return x == kNoData; })) {
        where[k] = 1;
        sourceMeters[k] =
            (1 - tv) * ((1 - tu) * s[0] + tu * s[1]) + tv * ((1 - tu) * s[2] + tu * s[3]);
        land[k] = std::all_of(std::begin(s), std::end(s), [](int16_t x) { return x > 0; }) ? 1 : 0;
      } else if (offData[source.index(r0, c0)] != 0 || offData[source.index(r0, c1)] != 0 ||
                 offData[source.index(r1, c0)] != 0 || offData[source.index(r1, c1)] != 0) {
        where[k] = 2;  // touches no data reaching the border: the footprint's edge is here
      }
      // A measured sample at or below 0 m among the four puts the coast there (coast rule).
      overNoData[k] =
          nearest == kNoData && std::none_of(std::begin(s), std::end(s),
                                             [](int16_t x) { return x != kNoData && x <= 0; })
              ? 1
              : 0;
    }
  }

  SourceFidelity result;
  result.level = level;
  result.noDataIsWater = noDataIsWater;
  std::vector<double> insideDifferences, bandDifferences, footprintSteps;
  for (int64_t row = lattice.firstRow; row < lattice.firstRow + lattice.rows; ++row) {
    const double lat = lattice.latitude(row);
    for (int64_t column = lattice.firstColumn; column < lattice.firstColumn + lattice.columns;
         ++column) {
      const size_t k = indexOf(row, column);
      if (where[k] != 1 || land[k] == 0) continue;
      const double lon = lattice.longitude(column);
      const auto drawn = static_cast<int16_t>(lattice.samples[k]);
      const double difference = std::abs(terrain::seaFloorMeters(drawn) - sourceMeters[k]);
      const double toEdge = std::min({lon - west, east - lon, lat - south, north - lat});
      (toEdge < edgeBandDegrees ? bandDifferences : insideDifferences).push_back(difference);
    }
  }
  result.inside = summarise(std::move(insideDifferences));
  result.edgeBand = summarise(std::move(bandDifferences));

  // Steps (the drawn surface, water at 0 m) to the east and south neighbour.
  auto surface = [&](size_t k) {
    return terrain::surfaceHeightMeters(static_cast<int16_t>(lattice.samples[k]));
  };
  struct Pair {
    int64_t row, column;
    double step;
  };
  std::vector<Pair> across;
  for (int64_t row = lattice.firstRow; row < lattice.firstRow + lattice.rows; ++row) {
    for (int64_t column = lattice.firstColumn; column < lattice.firstColumn + lattice.columns;
         ++column) {
      const size_t a = indexOf(row, column);
      for (auto [dr, dc] : {std::pair<int64_t, int64_t>{0, 1}, {1, 0}}) {
        if (row + dr >= lattice.firstRow + lattice.rows ||
            column + dc >= lattice.firstColumn + lattice.columns)
          continue;
        const size_t b = indexOf(row + dr, column + dc);
        if (where[a] == 0 || where[b] == 0) continue;
        const double step = std::abs(surface(a) - surface(b));
        if (where[a] == 1 && where[b] == 1) {
          footprintSteps.push_back(step);
        } else if (where[a] != where[b]) {
          across.push_back(
              {where[a] == 1 ? row : row + dr, where[a] == 1 ? column : column + dc, step});
        }
      }
    }
  }
  if (!footprintSteps.empty()) {
    const auto k =
        static_cast<std::ptrdiff_t>(static_cast<double>(footprintSteps.size() - 1) * 0.999);
    std::nth_element(footprintSteps.begin(), footprintSteps.begin() + k, footprintSteps.end());
    result.sourceP999StepMeters = footprintSteps[static_cast<size_t>(k)];
  }
  for (const Pair& p : across) {
    ++result.edgePairs;
    result.worstStepAcrossMeters = std::max(result.worstStepAcrossMeters, p.step);
    // 1.5× the largest step between the source's own neighbouring samples within 5 samples.
    const double lon = lattice.longitude(p.column), lat = lattice.latitude(p.row);
    const auto column = std::lround(
        std::clamp((lon - source.firstColumnLongitudeDegrees) / source.columnStepDegrees, 0.0,
                   static_cast<double>(source.cols - 1)));
    const auto row =
        std::lround(std::clamp((source.firstRowLatitudeDegrees - lat) / source.rowStepDegrees, 0.0,
                               static_cast<double>(source.rows - 1)));
    const double local = largestSourceStep(source, row, column, 5);
    const double bound = 1.5 * local;
    // Steps below a metre are the heights' own rounding, never a wall.
    if (p.step > std::max(bound, 1.0)) ++result.stepsOverLocalBound;
    if (bound > 0)
      result.worstLocalStepRatio = std::max(result.worstLocalStepRatio, p.step / bound);
  }

  // Vertices over no data drawn as water where the coarser surface (as given) is above 0 m at
  // the 2×2 source sample positions around them (the coast resolved to the source's own cell),
  // or where no coarser source says anything.
  auto coarserLandAt = [&](double lon, double lat) {
    for (const conditioning::DemGrid* grid : coarser) {
      if (const auto meters = coarseSurfaceMeters(*grid, lon, lat)) return *meters > 0.0;
    }
    return true;
  };
  for (int64_t row = lattice.firstRow; row < lattice.firstRow + lattice.rows; ++row) {
    const double lat = lattice.latitude(row);
    for (int64_t column = lattice.firstColumn; column < lattice.firstColumn + lattice.columns;
         ++column) {
      const size_t k = indexOf(row, column);
      if (overNoData[k] == 0 || noDataIsWater) continue;
      ++result.noDataVertices;
      if (!terrain::isWater(static_cast<int16_t>(lattice.samples[k]))) continue;
      const double lon = lattice.longitude(column);
      const double u = (lon - source.firstColumnLongitudeDegrees) / source.columnStepDegrees;
      const double v = (source.firstRowLatitudeDegrees - lat) / source.rowStepDegrees;
      bool overLand = true;
      for (const double cu : {std::floor(u), std::floor(u) + 1}) {
        for (const double rv : {std::floor(v), std::floor(v) + 1}) {
          overLand =
              overLand &&
              coarserLandAt(source.firstColumnLongitudeDegrees + cu * source.columnStepDegrees,
                            source.firstRowLatitudeDegrees - rv * source.rowStepDegrees);
        }
      }
      if (overLand) ++result.noDataDrawnAsSeaOverLand;
    }
  }
  return result;
}

}  // namespace globe::fidelity
