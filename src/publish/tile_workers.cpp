#include "publish/tile_workers.hpp"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace globe::publish {

unsigned tileWorkerCount(size_t count, unsigned threads) {
  const size_t most = std::max<size_t>(count, 1);
  return static_cast<unsigned>(std::clamp<size_t>(threads, 1, most));
}

Result<ExportReport> runTileJobs(size_t count, unsigned threads, const TileJob& job,
                                 const ExportProgress& progress) {
  const unsigned workers = tileWorkerCount(count, threads);
  std::vector<ExportReport> reports(workers);
  std::atomic<size_t> next{0};
  std::mutex mutex;  // guards failure, done and the progress calls
  std::optional<std::string> failure;
  uint64_t done = 0;
  if (progress) progress(0, count);
  const auto work = [&](unsigned worker) {
    for (size_t i = next++; i < count; i = next++) {
      auto made = job(worker, i, reports[worker]);
      const std::lock_guard lock(mutex);
      if (!made) {
        if (!failure) failure = made.error();
        next = count;  // the others stop after their tile
        return;
      }
      ++done;
      if (progress) progress(done, count);
    }
  };
  std::vector<std::thread> pool;
  for (unsigned worker = 1; worker < workers; ++worker) pool.emplace_back(work, worker);
  work(0);
  for (std::thread& thread : pool) thread.join();
  if (failure) return makeError(*failure);
  ExportReport total;
  for (const ExportReport& r : reports) {
    total.tilesWritten += r.tilesWritten;
    total.tilesKept += r.tilesKept;
    total.bytesWritten += r.bytesWritten;
  }
  return total;
}

}  // namespace globe::publish
