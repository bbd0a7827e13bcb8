// Runs each method `repeats` times on fresh copies of the holed grid, times the fill call alone
// and scores the first result.
#include "tools/bench_fill/fill_benchmark.hpp"

#include <algorithm>
#include <chrono>

namespace globe::bench_fill {
namespace {

constexpr int16_t kNoData = -9999;

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

struct Run {
  std::vector<int16_t> samples;
  double seconds = 0;
  conditioning::FillStats stats;
};

Result<Run> runOnce(const FillMethod& method, const conditioning::DemGrid& holed,
                    const std::vector<uint8_t>& isVoid,
                    const conditioning::FillOptions& fillOptions) {
  Run run;
  if (method.kind == FillMethod::Kind::Gdal) {
    auto filled = gdalFillNodata(holed, isVoid, method.gdal);
    if (!filled) return Error{filled.error()};
    run.samples = std::move(filled->samples);
    run.seconds = filled->fillSeconds;
    return run;
  }
  conditioning::DemGrid grid = holed;
  conditioning::FillOptions options = fillOptions;
  if (method.harmonicOnly) options.minimumCurvatureMaxSamples = 0;
  const auto start = std::chrono::steady_clock::now();
  run.stats = conditioning::fillVoids(grid, isVoid, method.coarser, options);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.samples = std::move(grid.samples);
  return run;
}

}  // namespace

Result<std::vector<ClassResult>> benchmarkTile(const conditioning::DemGrid& truth,
                                               const std::vector<FillMethod>& methods,
                                               const std::vector<HoleClass>& classes,
                                               const BenchOptions& options) {
  std::vector<ClassResult> results;
  for (const HoleClass& holeClass : classes) {
    HolePlacement placement = options.placement;
    placement.seed += 1000003 * static_cast<uint64_t>(holeClass.diameterSamples * 10);
    const std::vector<Hole> holes =
        placeHoles(truth, holeClass.diameterSamples, holeClass.holes, placement);
    ClassResult result;
    result.diameterSamples = holeClass.diameterSamples;
    result.holesWanted = holeClass.holes;
    result.holes = holes.size();
    for (const Hole& hole : holes) result.samples += hole.samples.size();
    if (holes.empty()) {
      results.push_back(std::move(result));
      continue;
    }
    const std::vector<uint8_t> isVoid = voidMask(truth, holes);
    conditioning::DemGrid holed = truth;
    for (size_t i = 0; i < isVoid.size(); ++i) {
      if (isVoid[i]) holed.samples[i] = kNoData;
    }
    for (const FillMethod& method : methods) {
      MethodResult scored;
      scored.label = method.label;
      std::vector<double> seconds;
      std::vector<int16_t> first;
      for (int repeat = 0; repeat < std::max(1, options.repeats); ++repeat) {
        auto run = runOnce(method, holed, isVoid, options.fill);
        if (!run) return Error{method.label + ": " + run.error()};
        seconds.push_back(run->seconds);
        if (repeat == 0) {
          first = std::move(run->samples);
          scored.stats = run->stats;
        } else if (run->samples != first) {
          scored.deterministic = false;
        }
      }
      scored.medianFillMilliseconds = 1e3 * median(seconds);
      scored.error = summariseErrors(first, truth.samples, holes);
      conditioning::DemGrid filled = truth;
      filled.samples = std::move(first);
      scored.border = checkBorderRange(filled, truth, holes, isVoid);
      result.methods.push_back(std::move(scored));
    }
    results.push_back(std::move(result));
  }
  return results;
}

}  // namespace globe::bench_fill
