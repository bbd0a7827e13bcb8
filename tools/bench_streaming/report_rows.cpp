#include "report_rows.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace globe::bench {

double percentileMs(std::vector<double> seconds, double p) {
  if (seconds.empty()) return 0;
  std::sort(seconds.begin(), seconds.end());
  const auto rank = static_cast<size_t>(std::ceil(p / 100 * static_cast<double>(seconds.size())));
  return 1e3 * seconds[std::clamp<size_t>(rank, 1, seconds.size()) - 1];
}

std::string countText(uint64_t value) { return std::to_string(value); }

std::string millisecondsText(double milliseconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f ms", milliseconds);
  return text;
}

std::string kibibytesText(size_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f KiB", static_cast<double>(bytes) / 1024);
  return text;
}

void printRow(const std::string& metric, const std::string& value) {
  static bool headerPrinted = false;
  if (!headerPrinted) {
    std::printf("| %-44s | %22s |\n|%s|%s|\n", "metric", "value", std::string(46, '-').c_str(),
                std::string(24, '-').c_str());
    headerPrinted = true;
  }
  std::printf("| %-44s | %22s |\n", metric.c_str(), value.c_str());
}

}  // namespace globe::bench
