// An elevation profile as a chart a person reads at a glance: the terrain's height against the
// distance along the path as a filled area, axes with round ticks (m or km), the lowest and
// highest points marked, the total length, and the file's own elevations (a GPX track's <ele>)
// as a second line when it has them. Drawn by cairo into an image, or written as a PNG.
#pragma once

#include <filesystem>
#include <vector>

#include "core/result.hpp"
#include "formats/image_io.hpp"
#include "measure/elevation_profile.hpp"

namespace globe::measure {

inline constexpr int kMinChartWidthPixels = 300;
inline constexpr int kMinChartHeightPixels = 150;
inline constexpr int kMaxChartSidePixels = 10000;

// Where the data go inside a chart of that size (the rest: margins for labels, title, legend):
// distance 0 at left, the full length at left + width; heights upward from top + height.
struct ChartPlotArea {
  double left = 0;
  double top = 0;
  double width = 0;
  double height = 0;
};
ChartPlotArea profileChartPlotArea(int widthPixels, int heightPixels);

// Draws `rows` (two or more, distances increasing) into an opaque image of that size. Errors: a
// size out of range, too few rows, a failed draw.
Result<formats::ImageRgba> drawProfileChart(const std::vector<ProfileRow>& rows, int widthPixels,
                                            int heightPixels);

// drawProfileChart, then the PNG written atomically (a temporary name, then renamed). Errors name
// the file.
Result<void> writeProfileChartPng(const std::vector<ProfileRow>& rows,
                                  const std::filesystem::path& png, int widthPixels,
                                  int heightPixels);

}  // namespace globe::measure
