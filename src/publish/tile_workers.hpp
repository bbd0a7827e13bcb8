// Makes a run's tiles on several threads: tile i goes to whichever worker is free, each worker
// with its own state (a surface that caches blocks), so a tile's bytes are the same whoever makes
// it and the tree the same for any thread count. Progress is counted as tiles finish.
#pragma once

#include <cstddef>
#include <functional>

#include "core/result.hpp"
#include "publish/export_writes.hpp"

namespace globe::publish {

// Writes tile `index` on worker `worker` (0..threads-1), counting into that worker's report.
using TileJob = std::function<Result<void>(unsigned worker, size_t index, ExportReport& report)>;

// The number of workers runTileJobs uses for `count` tiles: 1..threads, no more than tiles.
unsigned tileWorkerCount(size_t count, unsigned threads);

// Runs job(worker, i, report) for i in 0..count-1 on tileWorkerCount(count, threads) threads
// (the calling one among them); the first error stops the others after their tile and is
// returned. `progress` (if set) hears (0, count) first, then (tiles done, count) as each
// finishes, from one thread at a time.
Result<ExportReport> runTileJobs(size_t count, unsigned threads, const TileJob& job,
                                 const ExportProgress& progress = {});

}  // namespace globe::publish
