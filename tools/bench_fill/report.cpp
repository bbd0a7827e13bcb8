// Markdown tables from the benchmark results.
#include "tools/bench_fill/report.hpp"

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <limits>
#include <optional>

namespace globe::bench_fill {
namespace {

__attribute__((format(printf, 1, 2))) std::string format(const char* pattern, ...) {
  va_list args;
  va_start(args, pattern);
  va_list again;
  va_copy(again, args);
  const int length = std::vsnprintf(nullptr, 0, pattern, args);
  va_end(args);
  std::string text(static_cast<size_t>(std::max(length, 0)) + 1, '\0');
  std::vsnprintf(text.data(), text.size(), pattern, again);
  va_end(again);
  text.pop_back();
  return text;
}

const MethodResult* find(const ClassResult& c, const std::string& label) {
  for (const MethodResult& m : c.methods) {
    if (m.label == label) return &m;
  }
  return nullptr;
}

std::string diameterKilometres(const TileReport& tile, const ClassResult& c) {
  const double kilometres = c.diameterSamples * tile.rowStepKilometres;
  return format(kilometres < 10 ? "%.1f" : "%.0f", kilometres);
}

void appendSetup(const ReportInput& in, std::string& out) {
  out += "## Setup\n\n";
  out +=
      "Tiles (the truth; holes only where every sample of the hole and of its "
      "8-neighbour ring is land above 0 m):\n\n";
  out +=
      "| tile | what | grid | step | land samples | no-data samples |\n|---|---|---|---|---|---|\n";
  for (const TileReport& t : in.tiles) {
    out += format("| %s | %s | %lld×%lld | %g″ (%.0f m N–S) | %zu | %zu |\n", t.name.c_str(),
                  t.description.c_str(), static_cast<long long>(t.cols),
                  static_cast<long long>(t.rows), t.stepArcSeconds, 1e3 * t.rowStepKilometres,
                  t.landSamples, t.noDataSamples);
  }
  out += format(
      "\nHoles: deterministic (seed %llu), round blobs whose radius wobbles by up to ±30%% with "
      "direction, 4-connected, at least %lld samples from the tile edge and %lld samples apart; "
      "each size class is cut and filled separately (all holes of a class in one grid, one fill "
      "call). Ø is the nominal diameter in samples (km north–south in the tables).\n\n",
      static_cast<unsigned long long>(in.options.placement.seed),
      static_cast<long long>(in.options.placement.edgeMarginSamples),
      static_cast<long long>(in.options.placement.gapSamples));
  out += "Methods, all on the same holes in the same run:\n\n";
  out += format(
      "- **globe**: `conditioning::fillVoids` (src/conditioning/void_fill.hpp). Voids up to "
      "`smallVoidMaxSamples` "
      "= %lld, and all voids when there is no coarser source, by interpolation from the border; "
      "larger ones by the delta surface over the coarser source. The interpolation (of the "
      "heights, or of the fine − coarse difference) is harmonic (multigrid beyond 1,024 "
      "samples), refined to minimum curvature in tension T = %.2f for voids up to "
      "`minimumCurvatureMaxSamples` = %lld. **globe, harmonic only** skips that refinement, to "
      "show what it adds.\n",
      static_cast<long long>(in.options.fill.smallVoidMaxSamples), in.options.fill.tension,
      static_cast<long long>(in.options.fill.minimumCurvatureMaxSamples));
  out += in.coarserNote;
  out += format(
      "- **GDAL**: `GDALFillNodata` (%s) through the C API on an in-memory (MEM) Int16 band with "
      "the holes as no-data -9999, max search distance %g pixels, smoothing iterations 0 "
      "(gdal_fillnodata.py's default) and 2 (`si=2`); this is exactly what `gdal_fillnodata.py "
      "-md %g [-si 2]` runs. The Int16 band rounds the fill to whole metres, like globe's.\n\n",
      in.gdalVersion.c_str(), in.gdalMaxSearchDistancePixels, in.gdalMaxSearchDistancePixels);
  out += format(
      "Metrics over all hole samples of a class: RMSE, p99 (nearest rank) and max of |filled − "
      "truth|, bias = mean(filled − truth), all in metres; fill time = the fill call alone "
      "(no copies), median of %d runs, single-threaded, on a machine with %u hardware threads "
      "shared with other work, so times are indicative. Whole run: %.0f s.\n\n",
      in.options.repeats, in.hardwareThreads, in.totalSeconds);
}

void appendSummary(const ReportInput& in, std::string& out) {
  out += "## Summary: RMSE / p99 of |filled − truth| (m), best RMSE in bold\n\n";
  out += "| tile | Ø samples (km) | holes | samples |";
  for (const std::string& label : in.methodLabels) out += " " + label + " |";
  out += "\n|---|---|---|---|";
  for (size_t i = 0; i < in.methodLabels.size(); ++i) out += "---|";
  out += "\n";
  for (const TileReport& t : in.tiles) {
    for (const ClassResult& c : t.classes) {
      out += format("| %s | %g (%s) | %zu | %zu |", t.name.c_str(), c.diameterSamples,
                    diameterKilometres(t, c).c_str(), c.holes, c.samples);
      if (c.methods.empty()) {
        for (size_t i = 0; i < in.methodLabels.size(); ++i) out += " no room |";
        out += "\n";
        continue;
      }
      double best = std::numeric_limits<double>::infinity();
      for (const MethodResult& m : c.methods) best = std::min(best, m.error.rmseMeters);
      for (const std::string& label : in.methodLabels) {
        const MethodResult* m = find(c, label);
        if (!m) {
          out += " n/a |";
          continue;
        }
        const bool isBest = m->error.rmseMeters == best;
        out += format(" %s%.2f%s / %.0f |", isBest ? "**" : "", m->error.rmseMeters,
                      isBest ? "**" : "", m->error.p99Meters);
      }
      out += "\n";
    }
  }
  out += "\n";
}

// "0.81–0.96" (min–max over the tile's classes in range) of method RMSE ÷ reference RMSE.
std::string ratioRange(const ReportInput& in, const TileReport& tile, const std::string& label,
                       double minDiameter, double maxDiameter) {
  double low = std::numeric_limits<double>::infinity(), high = 0;
  for (const ClassResult& c : tile.classes) {
    if (c.diameterSamples < minDiameter || c.diameterSamples > maxDiameter) continue;
    const MethodResult* m = find(c, label);
    const MethodResult* reference = find(c, in.gdalReferenceLabel);
    if (!m || !reference || reference->error.rmseMeters <= 0) continue;
    const double ratio = m->error.rmseMeters / reference->error.rmseMeters;
    low = std::min(low, ratio);
    high = std::max(high, ratio);
  }
  if (high == 0) return "n/a";
  return low == high ? format("%.2f", low) : format("%.2f–%.2f", low, high);
}

void appendGoal(const ReportInput& in, std::string& out) {
  // The goal: no worse than GDAL on small holes, better on large ones where a coarser source helps.
  constexpr double kSmallMax = 20, kLargeMin = 50;
  out += format("## Against the goal (RMSE ÷ %s RMSE; below 1 is better than GDAL)\n\n| tile |",
                in.gdalReferenceLabel.c_str());
  std::vector<std::string> labels;
  for (const std::string& label : in.methodLabels) {
    if (label.starts_with("globe")) labels.push_back(label);
  }
  for (const std::string& label : labels) {
    out += format(" %s, Ø ≤ %g | %s, Ø ≥ %g |", label.c_str(), kSmallMax, label.c_str(), kLargeMin);
  }
  out += "\n|---|";
  for (size_t i = 0; i < labels.size(); ++i) out += "---|---|";
  out += "\n";
  for (const TileReport& t : in.tiles) {
    out += "| " + t.name + " |";
    for (const std::string& label : labels) {
      out += " " + ratioRange(in, t, label, 0, kSmallMax) + " | " +
             ratioRange(in, t, label, kLargeMin, 1e9) + " |";
    }
    out += "\n";
  }
  out += "\n";
}

void appendDetails(const ReportInput& in, std::string& out) {
  out += format(
      "## Details\n\n| tile | Ø | method | RMSE m | p99 m | max m | bias m | fill ms | RMSE vs "
      "%s | from coarser |\n|---|---|---|---|---|---|---|---|---|---|\n",
      in.gdalReferenceLabel.c_str());
  for (const TileReport& t : in.tiles) {
    for (const ClassResult& c : t.classes) {
      const MethodResult* reference = find(c, in.gdalReferenceLabel);
      for (const MethodResult& m : c.methods) {
        const double samples = static_cast<double>(c.samples);
        const std::string fromCoarser =
            m.label.starts_with("globe")
                ? format("%.0f%%",
                         100.0 * static_cast<double>(m.stats.fromCoarserSamples) / samples)
                : "";
        const std::string ratio =
            reference && reference->error.rmseMeters > 0
                ? format("%.2f×", m.error.rmseMeters / reference->error.rmseMeters)
                : "";
        out += format("| %s | %g | %s | %.2f | %.0f | %.0f | %+.2f | %.1f | %s | %s |\n",
                      t.name.c_str(), c.diameterSamples, m.label.c_str(), m.error.rmseMeters,
                      m.error.p99Meters, m.error.maxMeters, m.error.biasMeters,
                      m.medianFillMilliseconds, ratio.c_str(), fromCoarser.c_str());
      }
    }
  }
  out += "\n";
}

void appendChecks(const ReportInput& in, std::string& out) {
  out += "## Checks\n\n";
  for (const TileReport& t : in.tiles) {
    size_t outside = 0, holeSamples = 0;
    for (const ClassResult& c : t.classes) {
      if (const MethodResult* m = find(c, in.interpolationLabel)) {
        outside += m->border.outsideBorderRange;
        holeSamples += m->border.holeSamples;
      }
    }
    out += format(
        "- %s, %s: %zu of %zu filled samples outside their hole border's [min, max] "
        "(%.4f%%).\n",
        t.name.c_str(), in.interpolationLabel.c_str(), outside, holeSamples,
        holeSamples ? 100.0 * static_cast<double>(outside) / static_cast<double>(holeSamples)
                    : 0.0);
  }
  std::vector<std::string> nondeterministic, changedOutside;
  for (const TileReport& t : in.tiles) {
    for (const ClassResult& c : t.classes) {
      for (const MethodResult& m : c.methods) {
        const std::string where =
            format("%s Ø%g %s", t.name.c_str(), c.diameterSamples, m.label.c_str());
        if (!m.deterministic) nondeterministic.push_back(where);
        if (m.border.changedOutsideHoles) {
          changedOutside.push_back(where + format(" (%zu)", m.border.changedOutsideHoles));
        }
      }
    }
  }
  auto list = [](const std::vector<std::string>& items) {
    std::string joined;
    for (const std::string& item : items) joined += (joined.empty() ? "" : "; ") + item;
    return joined;
  };
  out +=
      format("- Same samples in all %d runs of every method and class: %s.\n", in.options.repeats,
             nondeterministic.empty() ? "yes" : ("no: " + list(nondeterministic)).c_str());
  out += "- Valid samples outside the holes changed by a fill: " +
         (changedOutside.empty() ? std::string("none") : list(changedOutside)) + ".\n";
}

}  // namespace

std::string markdownReport(const ReportInput& in) {
  std::string out;
  out += "# Void-fill accuracy: globe's `conditioning::fillVoids` against GDAL's `gdal_fillnodata`\n\n";
  out += "Generated by `globe-bench-fill` (tools/bench_fill); do not edit by hand. Command:\n\n";
  out += "```sh\n" + in.commandLine + "\n```\n\n";
  appendSetup(in, out);
  appendSummary(in, out);
  appendGoal(in, out);
  appendDetails(in, out);
  appendChecks(in, out);
  return out;
}

}  // namespace globe::bench_fill
