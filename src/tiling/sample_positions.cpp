#include "tiling/sample_positions.hpp"

#include "geo/tiling_scheme.hpp"
#include "terrain/block_grid.hpp"
#include "terrain/height_block.hpp"

namespace globe::tiling {

uint32_t positionsPerTile(uint32_t verticesPerSide) {
  return verticesPerSide * verticesPerSide +
         static_cast<uint32_t>(terrain::apronSampleCount(verticesPerSide));
}

std::vector<SamplePosition> sourcePositions(const TilingPlan& plan, const geo::TileId& tile,
                                            uint32_t verticesPerSide) {
  const uint32_t n = verticesPerSide;
  const uint32_t half = (n - 1) / 2;
  std::vector<bool> filled(size_t{n} * n, false);
  const auto children = tile.children();
  for (size_t q = 0; q < children.size(); ++q) {
    if (!plan.exists(children[q])) continue;
    const uint32_t rowOffset = q >= 2 ? half : 0;
    const uint32_t columnOffset = q % 2 == 1 ? half : 0;
    for (uint32_t i = 0; i <= half; ++i) {
      for (uint32_t j = 0; j <= half; ++j)
        filled[size_t{rowOffset + i} * n + columnOffset + j] = true;
    }
  }
  std::vector<SamplePosition> positions;
  const terrain::BlockGrid grid{tile, n};
  for (uint32_t i = 0; i < n; ++i) {
    for (uint32_t j = 0; j < n; ++j) {
      if (filled[size_t{i} * n + j]) continue;
      positions.push_back({i * n + j, grid.longitudeDegrees(j), grid.latitudeDegrees(i),
                           SamplePosition::From::Vertex});
    }
  }
  const auto side = static_cast<int>(n);
  constexpr int w = terrain::kApronWidth;
  const size_t apronBegin = positions.size();
  positions.resize(apronBegin + terrain::apronSampleCount(n));
  for (int row = -w; row < side + w; ++row) {
    for (int column = -w; column < side + w; ++column) {
      if (row >= 0 && row < side && column >= 0 && column < side) continue;
      const terrain::BlockGrid::Vertex where = grid.wrappedVertex(row, column);
      const bool beyondPole =
          (row < 0 && tile.y == 0) ||
          (row >= side && tile.y + 1 == geo::GeographicTilingScheme::tilesY(tile.level));
      const size_t apron = terrain::apronIndex(row, column, n);
      positions[apronBegin + apron] = {
          static_cast<uint32_t>(n * n + apron), where.longitudeDegrees, where.latitudeDegrees,
          beyondPole ? SamplePosition::From::OverThePole : SamplePosition::From::Apron};
    }
  }
  return positions;
}

namespace {

double apronReachDegrees(uint32_t level, uint32_t n) {
  return terrain::kApronWidth * terrain::vertexSpacingDegrees(level, n);
}

}  // namespace

StripSamplers::StripSamplers(const std::vector<TilerSource>& sources, const TilingPlan& plan,
                             const geo::TileId& westTile, const geo::TileId& eastTile,
                             uint32_t verticesPerSide)
    : vertices_(
          sources, westTile.level,
          terrain::BlockGrid{westTile, verticesPerSide}.longitudeDegrees(0),
          terrain::BlockGrid{eastTile, verticesPerSide}.longitudeDegrees(verticesPerSide - 1)),
      apron_(sources, plan.maxLevel(),
             terrain::BlockGrid{westTile, verticesPerSide}.longitudeDegrees(0) -
                 apronReachDegrees(westTile.level, verticesPerSide),
             terrain::BlockGrid{eastTile, verticesPerSide}.longitudeDegrees(verticesPerSide - 1) +
                 apronReachDegrees(westTile.level, verticesPerSide)) {
  const double reach = apronReachDegrees(westTile.level, verticesPerSide);
  const bool polar =
      westTile.y == 0 || westTile.y + 1 == geo::GeographicTilingScheme::tilesY(westTile.level);
  if (polar) {
    overThePole_.emplace(
        sources, plan.maxLevel(),
        terrain::BlockGrid{westTile, verticesPerSide}.longitudeDegrees(0) + 180.0 - reach,
        terrain::BlockGrid{eastTile, verticesPerSide}.longitudeDegrees(verticesPerSide - 1) +
            180.0 + reach);
  }
}

Result<int16_t> StripSamplers::sample(const SamplePosition& position) {
  switch (position.from) {
    case SamplePosition::From::Vertex:
      return vertices_.sample(position.longitudeDegrees, position.latitudeDegrees);
    case SamplePosition::From::Apron:
      return apron_.sample(position.longitudeDegrees, position.latitudeDegrees);
    case SamplePosition::From::OverThePole:
      return overThePole_->sample(position.longitudeDegrees, position.latitudeDegrees);
  }
  return makeError("internal: unknown sample position");
}

}  // namespace globe::tiling
