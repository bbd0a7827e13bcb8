// globe-bench-streaming: flies a scripted path over a real pyramid with a small cache budget
// and a thread pool, and prints what the loader and cache did (a table, not a timed test).
#include <unistd.h>
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "bundled_pyramid.hpp"
#include "core/thread_pool_runner.hpp"
#include "flight_path.hpp"
#include "report_rows.hpp"
#include "streaming/block_cache.hpp"
#include "streaming/tile_loader.hpp"
#include "streaming/tile_store.hpp"
#include "wanted_tiles.hpp"

namespace {

using namespace globe;

struct LegTotals {
  size_t steps = 0;
  uint64_t requests = 0;
  uint64_t arrivals = 0;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Streams a scripted flight through a tile pyramid and reports the loader's work."};
  std::string pyramid;
  double budgetMegabytes = 2;
  unsigned threads = 2;
  size_t maxInFlight = streaming::TileLoader::kDefaultMaxInFlight;
  size_t stepsPerLeg = 1500;
  double frameMilliseconds = 1;
  app.add_option("--pyramid", pyramid,
                 "pyramid directory (default: tile the bundled data/dem into a temp dir)");
  app.add_option("--budget-mb", budgetMegabytes, "cache budget in MiB")->capture_default_str();
  app.add_option("--threads", threads, "loader threads")->capture_default_str();
  app.add_option("--max-in-flight", maxInFlight, "loads at once")->capture_default_str();
  app.add_option("--steps-per-leg", stepsPerLeg, "frames per leg of the flight")
      ->capture_default_str();
  app.add_option("--frame-ms", frameMilliseconds, "simulated frame time (the loop sleeps it)")
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  std::filesystem::path scratch;
  if (pyramid.empty()) {
    scratch = std::filesystem::temp_directory_path() /
              ("globe-bench-streaming-" + std::to_string(::getpid()));
    auto tiled = bench::tileBundledPyramid(scratch);
    if (!tiled) {
      std::fprintf(stderr, "globe-bench-streaming: %s\n", tiled.error().c_str());
      return 1;
    }
    pyramid = tiled->string();
  }
  // A pyramid's URL is read as `globe` reads one by default (a missing disk cache said).
  auto opened =
      streaming::TileStore::open(pyramid, terrain::SeaSurface::Water, bench::defaultNetwork());
  if (!opened) {
    std::fprintf(stderr, "globe-bench-streaming: %s\n", opened.error().c_str());
    return 1;
  }
  streaming::TileStore& store = **opened;

  const auto budgetBytes = static_cast<size_t>(budgetMegabytes * 1024 * 1024);
  streaming::BlockCache cache(budgetBytes);
  core::ThreadPoolRunner pool(threads);
  streaming::TileLoader loader(store, pool, cache);
  loader.setMaxInFlight(maxInFlight);

  const std::vector<bench::CameraSample> path = bench::scriptedFlight(stepsPerLeg);
  const auto frame = std::chrono::duration<double, std::milli>(frameMilliseconds);
  std::vector<double> workerSeconds, visibleSeconds;
  std::set<geo::TileId> distinctTiles;
  std::map<std::string, LegTotals> legs;
  std::vector<std::string> legOrder;
  uint64_t requests = 0, framesWithArrivals = 0, ruleViolations = 0;
  size_t maxOverBudgetBytes = 0;
  std::vector<geo::TileId> drawn;

  auto collect = [&](const streaming::PollResult& result, LegTotals* leg) {
    for (const auto& arrival : result.arrived) {
      workerSeconds.push_back(arrival.workerLatencySeconds);
      visibleSeconds.push_back(arrival.visibleLatencySeconds);
    }
    for (const streaming::LoadError& error : result.errors) {
      std::fprintf(stderr, "load failed: %s\n", error.message.c_str());
    }
    if (!result.arrived.empty()) ++framesWithArrivals;
    if (leg) leg->arrivals += result.arrived.size();
    // The cache's rule: over budget only by the frame's pinned tiles.
    const streaming::BlockCacheCounters& c = cache.counters();
    if (c.residentBytes > std::max(budgetBytes, c.pinnedBytes)) ++ruleViolations;
    if (c.residentBytes > budgetBytes) {
      maxOverBudgetBytes = std::max(maxOverBudgetBytes, c.residentBytes - budgetBytes);
    }
  };

  const auto started = std::chrono::steady_clock::now();
  for (const bench::CameraSample& camera : path) {
    if (!legs.contains(camera.leg)) legOrder.push_back(camera.leg);
    LegTotals& leg = legs[camera.leg];
    ++leg.steps;
    cache.beginFrame();
    const std::vector<streaming::LoadRequest> wanted = bench::wantedTiles(camera, store.manifest());
    // The frame draws what is resident of what it wants (a real viewer draws parents for the
    // rest); looking them up counts the cache's hits and misses.
    drawn.clear();
    for (const streaming::LoadRequest& r : wanted) {
      distinctTiles.insert(r.tile);
      const streaming::TileState state = loader.state(r.tile);
      if (state == streaming::TileState::Absent || state == streaming::TileState::Failed) continue;
      if (loader.get(r.tile)) drawn.push_back(r.tile);
    }
    cache.touch(drawn);
    loader.request(wanted);
    requests += wanted.size();
    leg.requests += wanted.size();
    collect(loader.poll(), &leg);
    std::this_thread::sleep_for(frame);
  }
  // Let the last loads land, so that the counters add up.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (loader.counters().inFlight > 0 && std::chrono::steady_clock::now() < deadline) {
    cache.beginFrame();
    collect(loader.poll(), nullptr);
    std::this_thread::sleep_for(frame);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  const streaming::LoaderCounters l = loader.counters();
  const streaming::BlockCacheCounters& c = cache.counters();
  size_t distinctBytes = 0;
  for (const geo::TileId& tile : distinctTiles) {
    if (cache.contains(tile) || loader.state(tile) != streaming::TileState::Absent) {
      distinctBytes +=
          size_t{store.manifest().verticesPerSide} * store.manifest().verticesPerSide * 2 +
          streaming::BlockCache::kEntryOverheadBytes;
    }
  }

  using bench::percentileMs;
  auto row = bench::printRow;
  auto num = bench::countText;
  auto ms = bench::millisecondsText;
  auto kib = bench::kibibytesText;

  std::printf("globe-bench-streaming: %s\n", pyramid.c_str());
  std::printf("%zu frames of %.2f ms, %zu threads, at most %zu loads in flight, budget %s\n\n",
              path.size(), frameMilliseconds, pool.threadCount(), loader.maxInFlight(),
              kib(budgetBytes).c_str());
  for (const std::string& name : legOrder) {
    const LegTotals& leg = legs[name];
    row("steps: " + name, num(leg.steps) + " (" + num(leg.arrivals) + " arrived)");
  }
  row("steps", num(path.size()));
  row("requests (wanted tiles, summed over frames)", num(requests));
  row("distinct tiles wanted", num(distinctTiles.size()));
  row("their blocks' bytes (present tiles)", kib(distinctBytes));
  row("tiles queued (loader: requested)", num(l.requested));
  row("loads started", num(l.started));
  row("loads completed (cache: loads)", num(l.completed) + " (" + num(c.loads) + ")");
  row("loads cancelled", num(l.cancelled));
  row("absent / failed", num(l.absent) + " / " + num(l.failed));
  row("cache hits", num(c.hits));
  row("cache misses", num(c.misses));
  row("evictions", num(c.evictions));
  row("budget", kib(budgetBytes));
  row("peak resident bytes", kib(c.peakResidentBytes));
  row("peak pinned bytes (one frame's tiles)", kib(c.peakPinnedBytes));
  row("most over budget (all pinned)", kib(maxOverBudgetBytes));
  row("resident <= max(budget, pinned) every frame",
      ruleViolations == 0 ? "yes" : "NO: " + num(ruleViolations) + " frames");
  row("frames with arrivals", num(framesWithArrivals));
  row("load latency median (post -> done)", ms(percentileMs(workerSeconds, 50)));
  row("load latency p99 (post -> done)", ms(percentileMs(workerSeconds, 99)));
  row("visible latency median (post -> poll)", ms(percentileMs(visibleSeconds, 50)));
  row("visible latency p99 (post -> poll)", ms(percentileMs(visibleSeconds, 99)));
  row("store block reads", num(store.blockReads()));
  row("wall time", ms(seconds * 1e3));

  if (!scratch.empty()) std::filesystem::remove_all(scratch);
  const bool withinBudget =
      ruleViolations == 0 && c.peakResidentBytes <= std::max(budgetBytes, c.peakPinnedBytes);
  return withinBudget && l.inFlight == 0 ? 0 : 1;
}
