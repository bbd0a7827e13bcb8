// Conditions the tiler's sources before tiling (conditioning/condition.hpp): each is read into
// memory and, from the coarsest to the finest, its sea told from its voids, its voids filled and,
// outside its footprint, the coarser sources (as already conditioned) bent to meet its edge. Each
// source's raster is then replaced by its conditioned copy, so the sampler sees only these.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "core/result.hpp"
#include "formats/pyramid_manifest.hpp"
#include "tiling/source_set.hpp"

namespace globe::tiling {

// Outside a finer source's footprint the coarser surface bends to meet its edge over this many of
// the next coarser source's cells: the coarser source places its features within about a cell.
inline constexpr double kBendMarginCoarserCells = 1.5;

struct ConditioningOptions {
  unsigned threads = 1;  // equally fine sources are conditioned in parallel
  // Conditioned sources beyond this many bytes of samples are spilled to unlinked files here
  // (none when empty), except those a finer source still reads as its coarser one.
  std::filesystem::path spillDirectory;
  uint64_t memoryBudgetBytes = uint64_t{256} << 20;
};

// coarser[i]: the sources coarser than source i that reach it, finest first: the ones its
// conditioning reads (sources finest first, openSources' order).
std::vector<std::vector<size_t>> coarserSourcesReaching(const std::vector<TilerSource>& sources);

// The bend margin a source gets from the coarser sources reaching it (0 with none).
double bendMarginDegrees(const std::vector<TilerSource>& sources,
                         const std::vector<size_t>& coarserReaching);

// sources: finest first (openSources' order). Returns each source's conditioning, same order.
Result<std::vector<formats::SourceConditioning>> conditionSources(
    std::vector<TilerSource>& sources, const ConditioningOptions& options = {});

}  // namespace globe::tiling
