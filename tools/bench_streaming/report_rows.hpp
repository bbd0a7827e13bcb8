// The benchmark's table: its cells as text ("12", "3.250 ms", "4.0 KiB") and its rows printed as
// one Markdown table.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace globe::bench {

// Nearest-rank percentile in milliseconds; 0 for no samples.
double percentileMs(std::vector<double> seconds, double p);

std::string countText(uint64_t value);
std::string millisecondsText(double milliseconds);
std::string kibibytesText(size_t bytes);

// Prints the header row once on the first call, then the row.
void printRow(const std::string& metric, const std::string& value);

}  // namespace globe::bench
