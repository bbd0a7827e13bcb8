#include "tiling/source_conditioning.hpp"

#include <algorithm>
#include <atomic>
#include <memory>
#include <mutex>
#include <new>
#include <thread>

#include "conditioning/condition.hpp"
#include "conditioning/grid_coarser_sources.hpp"
#include "tiling/conditioned_raster.hpp"
#include "tiling/dem_reader.hpp"

namespace globe::tiling {
namespace {

constexpr double kSameStepTolerance = 1e-6;

bool extentsMeet(const formats::BoundsDegrees& a, const formats::BoundsDegrees& b) {
  return a.west <= b.east && b.west <= a.east && a.south <= b.north && b.south <= a.north;
}

}  // namespace

std::vector<std::vector<size_t>> coarserSourcesReaching(const std::vector<TilerSource>& sources) {
  const size_t count = sources.size();
  std::vector<std::vector<size_t>> coarser(count);
  for (size_t i = 0; i < count; ++i) {
    for (size_t j = i + 1; j < count; ++j) {
      if (sources[j].stepDegrees <= sources[i].stepDegrees * (1 + kSameStepTolerance)) continue;
      if (!sources[j].grid.wrapsLongitude && !sources[i].grid.wrapsLongitude &&
          !extentsMeet(sources[j].extent, sources[i].extent)) {
        continue;
      }
      coarser[i].push_back(j);
    }
  }
  return coarser;
}

double bendMarginDegrees(const std::vector<TilerSource>& sources,
                         const std::vector<size_t>& coarserReaching) {
  if (coarserReaching.empty()) return 0.0;
  return kBendMarginCoarserCells * sources[coarserReaching.front()].stepDegrees;
}

Result<std::vector<formats::SourceConditioning>> conditionSources(
    std::vector<TilerSource>& sources, const ConditioningOptions& options) {
  const size_t count = sources.size();
  auto sameStep = [&](size_t a, size_t b) {
    return sources[a].stepDegrees <= sources[b].stepDegrees * (1 + kSameStepTolerance) &&
           sources[b].stepDegrees <= sources[a].stepDegrees * (1 + kSameStepTolerance);
  };
  const std::vector<std::vector<size_t>> coarser = coarserSourcesReaching(sources);
  std::vector<uint8_t> neededAsCoarser(count, 0);
  for (const auto& list : coarser) {
    for (size_t j : list) neededAsCoarser[j] = 1;
  }

  std::vector<std::shared_ptr<conditioning::DemGrid>> grids(count);
  std::vector<formats::SourceConditioning> report(count);
  // From here on a conditioned source is read like the original: in memory within the budget
  // (and always when a finer source still needs it), otherwise from a spilled copy, decided as
  // soon as it is conditioned so that a group of many inputs never sits in memory at once.
  // Every spilled source goes to one file, made when the first one spills.
  uint64_t bytesInMemory = 0;
  std::shared_ptr<SpillFile> spillFile;
  std::mutex budgetMutex;
  auto keepOrSpill = [&](size_t i) -> Result<void> {
    const uint64_t bytes = grids[i]->samples.size() * sizeof(int16_t);
    std::shared_ptr<SpillFile> spillTo;
    if (!neededAsCoarser[i] && !options.spillDirectory.empty()) {
      std::lock_guard lock(budgetMutex);
      if (bytesInMemory + bytes <= options.memoryBudgetBytes) {
        bytesInMemory += bytes;
      } else {
        if (!spillFile) {
          auto created = SpillFile::create(options.spillDirectory);
          if (!created) return Error{created.error()};
          spillFile = std::move(*created);
        }
        spillTo = spillFile;
      }
    }
    // The conditioned copy replaces the original, which closes.
    if (!spillTo) {
      sources[i].raster = makeMemoryRaster(*sources[i].raster, grids[i]);
      return {};
    }
    auto spilled = makeSpilledRaster(*sources[i].raster, *grids[i], std::move(spillTo));
    if (!spilled) return Error{spilled.error()};
    sources[i].raster = std::move(*spilled);
    grids[i].reset();
    return {};
  };
  auto conditionUnguarded = [&](size_t i) -> Result<void> {
    TilerSource& source = sources[i];
    if (auto opened = openRaster(source); !opened) return opened;
    auto read = readDemGrid(*source.raster, source.argument);
    if (!read) return Error{read.error()};
    auto grid = std::make_shared<conditioning::DemGrid>(std::move(*read));
    std::vector<const conditioning::DemGrid*> coarserGrids;
    for (size_t j : coarser[i]) coarserGrids.push_back(grids[j].get());
    const conditioning::GridCoarserSources coarserSources(coarserGrids);
    conditioning::ConditionOptions conditionOptions;
    conditionOptions.noDataIsWater = source.noDataIsWater;
    conditionOptions.bendMarginDegrees = bendMarginDegrees(sources, coarser[i]);
    const conditioning::ConditionStats stats = conditioning::conditionGrid(
        *grid, coarserGrids.empty() ? nullptr : &coarserSources, conditionOptions);
    report[i] = {stats.noDataSamples,
                 stats.seaSamples,
                 stats.voidSamples,
                 stats.fill.interpolatedSamples,
                 stats.fill.fromCoarserSamples,
                 stats.fill.unfilledSamples,
                 stats.outsideSamples,
                 conditionOptions.bendMarginDegrees,
                 source.noDataIsWater};
    grids[i] = std::move(grid);
    return keepOrSpill(i);
  };
  auto conditionOne = [&](size_t i) -> Result<void> {
    try {
      return conditionUnguarded(i);
    } catch (const std::bad_alloc&) {
      return makeError(sources[i].argument +
                       ": not enough memory to condition it (about 8 bytes a sample, up to "
                       "about 30 where much of it lies outside its footprint); split it into "
                       "tiles (e.g. gdal_retile.py) and give them all");
    }
  };

  // Coarsest first, a group of equally fine sources at a time (they do not depend on each
  // other, so a group runs in parallel).
  for (size_t end = count; end > 0;) {
    size_t begin = end - 1;
    while (begin > 0 && sameStep(begin - 1, end - 1)) --begin;
    std::atomic<size_t> next{begin};
    std::mutex mutex;
    std::string firstError;
    auto work = [&] {
      for (size_t i; (i = next++) < end;) {
        if (auto done = conditionOne(i); !done) {
          std::lock_guard lock(mutex);
          if (firstError.empty()) firstError = done.error();
          return;
        }
      }
    };
    const unsigned workers =
        static_cast<unsigned>(std::min<size_t>(std::max(1U, options.threads), end - begin));
    std::vector<std::thread> threads;
    for (unsigned w = 1; w < workers; ++w) threads.emplace_back(work);
    work();
    for (std::thread& t : threads) t.join();
    if (!firstError.empty()) return makeError(firstError);

    end = begin;
  }

  for (size_t i = 0; i < count; ++i) {
    TilerSource& source = sources[i];
    source.bendMarginDegrees = report[i].bendMarginDegrees;
    if (source.bendMarginDegrees > 0 && !source.grid.wrapsLongitude) {
      auto edges = readEdgeProfiles(*source.raster);
      if (!edges) return Error{edges.error()};
      source.edges = std::make_shared<const EdgeProfiles>(std::move(*edges));
    }
  }
  for (TilerSource& source : sources) {
    // The poles' one value, from the conditioned polar rows.
    if (source.northPoleHeight) {
      auto pole = polarRowHeight(*source.raster, 0);
      if (!pole) return Error{pole.error()};
      source.northPoleHeight = *pole;
    }
    if (source.southPoleHeight) {
      auto pole = polarRowHeight(*source.raster, source.grid.rows - 1);
      if (!pole) return Error{pole.error()};
      source.southPoleHeight = *pole;
    }
  }
  return report;
}

}  // namespace globe::tiling
