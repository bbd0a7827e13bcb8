// Percentiles, error statistics and the CSV, JSON and console forms of the accuracy rows.
#include "tools/bench/accuracy_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

namespace globe::bench {
namespace {

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const auto rank = static_cast<size_t>(std::ceil(p / 100.0 * static_cast<double>(values.size())));
  return values[std::clamp<size_t>(rank, 1, values.size()) - 1];
}
ErrorStats errorStats(const std::vector<const AccuracyQuery*>& queries, size_t method, bool drawn) {
  ErrorStats stats;
  std::vector<double> over;
  over.reserve(queries.size());
  double sum = 0;
  for (const AccuracyQuery* q : queries) {
    const double surface = drawn ? q->drawn : q->source;
    const double error = q->effectiveHeight[method] - surface;
    over.push_back(error);
    sum += error;
    const bool penetrating = q->cameraHeight <= surface;
    stats.penetrations += penetrating;
    if (penetrating && !q->collided[method]) {
      ++stats.falseNegatives;
      if (surface - q->cameraHeight <= kAccuracyRadiusMeters) ++stats.falseNegativesWithinRadius;
    }
    if (q->collided[method] && q->cameraHeight > surface + kAccuracyRadiusMeters)
      ++stats.falsePositives;
  }
  if (!over.empty()) {
    stats.mean = sum / static_cast<double>(over.size());
    stats.p99 = percentile(over, 99);
    stats.max = *std::max_element(over.begin(), over.end());
    stats.min = *std::min_element(over.begin(), over.end());
  }
  return stats;
}

nlohmann::json toJson(const ErrorStats& s) {
  return {{"mean_m", s.mean},
          {"p99_m", s.p99},
          {"max_m", s.max},
          {"min_m", s.min},
          {"penetrations", s.penetrations},
          {"false_negatives", s.falseNegatives},
          {"false_negatives_within_radius", s.falseNegativesWithinRadius},
          {"false_positives", s.falsePositives}};
}

}  // namespace

AccuracyRow summarise(const std::string& region, size_t method, size_t tiles,
                      const std::vector<const AccuracyQuery*>& queries, double bytesPerTile) {
  AccuracyRow row;
  row.region = region;
  row.method = kMethodNames[method];
  row.tiles = tiles;
  row.queries = queries.size();
  std::vector<double> times;
  times.reserve(queries.size());
  for (const AccuracyQuery* q : queries) times.push_back(q->nanoseconds[method]);
  row.medianNs = percentile(times, 50);
  row.p99Ns = percentile(times, 99);
  row.maxNs = times.empty() ? 0 : *std::max_element(times.begin(), times.end());
  for (double t : times) row.meanNs += t / static_cast<double>(times.size());
  row.drawn = errorStats(queries, method, true);
  row.source = errorStats(queries, method, false);
  row.bytesPerTile = bytesPerTile;
  return row;
}

void writeAccuracyFiles(const std::filesystem::path& dir, const std::vector<AccuracyRow>& rows,
                        const nlohmann::json& header) {
  std::filesystem::create_directories(dir);
  std::ofstream csv(dir / "accuracy.csv");
  csv << "region,method,tiles,queries,median_ns,p99_ns,max_ns,mean_ns,"
         "drawn_mean_m,drawn_p99_m,drawn_max_m,drawn_min_m,drawn_penetrations,drawn_fn,"
         "drawn_fn_within_radius,drawn_fp,source_mean_m,source_p99_m,source_max_m,source_min_m,"
         "source_penetrations,source_fn,source_fn_within_radius,source_fp,bytes_per_tile\n";
  nlohmann::json json = header;
  json["rows"] = nlohmann::json::array();
  for (const AccuracyRow& r : rows) {
    char line[1024];
    std::snprintf(line, sizeof line,
                  "%s,%s,%zu,%zu,%.1f,%.1f,%.1f,%.1f,%.3f,%.3f,%.3f,%.3f,%llu,%llu,%llu,%llu,"
                  "%.3f,%.3f,%.3f,%.3f,%llu,%llu,%llu,%llu,%.1f\n",
                  r.region.c_str(), r.method.c_str(), r.tiles, r.queries, r.medianNs, r.p99Ns,
                  r.maxNs, r.meanNs, r.drawn.mean, r.drawn.p99, r.drawn.max, r.drawn.min,
                  static_cast<unsigned long long>(r.drawn.penetrations),
                  static_cast<unsigned long long>(r.drawn.falseNegatives),
                  static_cast<unsigned long long>(r.drawn.falseNegativesWithinRadius),
                  static_cast<unsigned long long>(r.drawn.falsePositives), r.source.mean,
                  r.source.p99, r.source.max, r.source.min,
                  static_cast<unsigned long long>(r.source.penetrations),
                  static_cast<unsigned long long>(r.source.falseNegatives),
                  static_cast<unsigned long long>(r.source.falseNegativesWithinRadius),
                  static_cast<unsigned long long>(r.source.falsePositives), r.bytesPerTile);
    csv << line;
    json["rows"].push_back({{"region", r.region},
                            {"method", r.method},
                            {"tiles", r.tiles},
                            {"queries", r.queries},
                            {"median_ns", r.medianNs},
                            {"p99_ns", r.p99Ns},
                            {"max_ns", r.maxNs},
                            {"mean_ns", r.meanNs},
                            {"drawn", toJson(r.drawn)},
                            {"source", toJson(r.source)},
                            {"bytes_per_tile", r.bytesPerTile}});
  }
  std::ofstream(dir / "accuracy.json") << json.dump(1) << "\n";
}

void printAccuracyTable(const std::vector<AccuracyRow>& rows) {
  std::printf(
      "%-8s %-14s %6s %7s | %8s %8s %9s | %7s %7s %7s %5s %5s | %7s %7s %7s %7s %5s "
      "%5s | %7s\n",
      "region", "method", "tiles", "queries", "med ns", "p99 ns", "max ns", "mean m", "p99 m",
      "max m", "FN", "FP", "mean m", "p99 m", "max m", "min m", "FN", "FP", "B/tile");
  std::printf("%-38s | %-27s | %-38s | %-44s |\n", "", "time per query",
              "vs drawn surface (overestimate)", "vs finest source (overestimate)");
  for (const AccuracyRow& r : rows) {
    std::printf(
        "%-8s %-14s %6zu %7zu | %8.0f %8.0f %9.0f | %7.2f %7.2f %7.2f %5llu %5llu | "
        "%7.2f %7.2f %7.2f %7.2f %5llu %5llu | %7.0f\n",
        r.region.c_str(), r.method.c_str(), r.tiles, r.queries, r.medianNs, r.p99Ns, r.maxNs,
        r.drawn.mean, r.drawn.p99, r.drawn.max,
        static_cast<unsigned long long>(r.drawn.falseNegatives),
        static_cast<unsigned long long>(r.drawn.falsePositives), r.source.mean, r.source.p99,
        r.source.max, r.source.min, static_cast<unsigned long long>(r.source.falseNegatives),
        static_cast<unsigned long long>(r.source.falsePositives), r.bytesPerTile);
  }
}
}  // namespace globe::bench
