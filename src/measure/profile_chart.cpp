#include "measure/profile_chart.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <numbers>
#include <span>
#include <string>

#include "measure/chart_axis.hpp"
#include "transport/atomic_file.hpp"

namespace globe::measure {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr const char* kFont = "DejaVu Sans";

struct Rgb {
  double r, g, b;
};
constexpr Rgb kInk{0.15, 0.15, 0.15};
constexpr Rgb kGrid{0.86, 0.86, 0.86};
constexpr Rgb kTerrainTop{0.42, 0.66, 0.33};
constexpr Rgb kTerrainBottom{0.78, 0.87, 0.66};
constexpr Rgb kTerrainLine{0.18, 0.40, 0.16};
constexpr Rgb kFileLine{0.86, 0.32, 0.08};

// Sizes grow with the picture, so a 3000-pixel chart is not all margin and tiny text.
double chartScale(int widthPixels, int heightPixels) {
  return std::clamp(std::min(widthPixels / 1000.0, heightPixels / 400.0), 0.75, 3.0);
}

void setColor(cairo_t* cr, Rgb c, double alpha = 1) {
  cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha);
}

// 3776.2 -> "3,776": heights read faster with thousands separated.
std::string groupedInteger(double value) {
  char digits[32];
  std::snprintf(digits, sizeof digits, "%.0f", std::abs(value));
  std::string s = digits;
  for (int i = static_cast<int>(s.size()) - 3; i > 0; i -= 3) s.insert(static_cast<size_t>(i), ",");
  return (std::lround(value) < 0 ? "-" : "") + s;
}

// A tick value with as many decimals as the step needs (0.5 km: one).
std::string tickLabel(double value, double step) {
  const int decimals = step >= 1 ? 0 : static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
  if (decimals == 0) return groupedInteger(value);
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

std::string lengthText(double meters) {
  char text[48];
  if (meters < 2000) {
    std::snprintf(text, sizeof text, "%.0f m", meters);
  } else {
    std::snprintf(text, sizeof text, "%.*f km", meters < 10'000 ? 2 : 1, meters / 1000);
  }
  return text;
}

// The points to draw, at most two per half pixel column (that column's lowest and highest, in
// path order): a 2-million-sample profile draws as fast as a short one and looks the same. NaN
// heights (a file without elevations there) break the line.
std::vector<std::pair<double, double>> columnExtremes(const std::vector<ProfileRow>& rows,
                                                      double (*height)(const ProfileRow&),
                                                      double length, int columns) {
  std::vector<std::pair<double, double>> points;
  if (rows.size() <= static_cast<size_t>(columns) * 2) {
    for (const ProfileRow& r : rows) points.emplace_back(r.sample.distanceMeters, height(r));
    return points;
  }
  size_t i = 0;
  for (int column = 0; column < columns && i < rows.size(); ++column) {
    const double end = length * (column + 1) / columns;
    size_t lowest = rows.size(), highest = rows.size();
    bool broken = false;
    for (; i < rows.size() && (rows[i].sample.distanceMeters <= end || column == columns - 1);
         ++i) {
      const double h = height(rows[i]);
      if (std::isnan(h)) {
        broken = true;
        continue;
      }
      if (lowest == rows.size() || h < height(rows[lowest])) lowest = i;
      if (highest == rows.size() || h > height(rows[highest])) highest = i;
    }
    if (broken) points.emplace_back(rows[i - 1].sample.distanceMeters, kNaN);
    if (lowest == rows.size()) continue;
    for (const size_t k : {std::min(lowest, highest), std::max(lowest, highest)}) {
      points.emplace_back(rows[k].sample.distanceMeters, height(rows[k]));
    }
  }
  return points;
}

struct Frame {
  ChartPlotArea area;
  AxisRange heights;
  double lengthMeters = 0;
  double x(double distanceMeters) const {
    return area.left + area.width * distanceMeters / lengthMeters;
  }
  double y(double heightMeters) const {
    return area.top + area.height * (heights.high - heightMeters) / (heights.high - heights.low);
  }
};

enum class Align { kLeft, kCenter, kRight };

// Text with its baseline at y, aligned on x; returns its width.
double drawText(cairo_t* cr, const std::string& text, double x, double y, Align align) {
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  const double shift = align == Align::kLeft     ? 0
                       : align == Align::kCenter ? extents.x_advance / 2
                                                 : extents.x_advance;
  cairo_move_to(cr, x - shift, y);
  cairo_show_text(cr, text.c_str());
  return extents.x_advance;
}

void drawGridAndAxes(cairo_t* cr, const Frame& f, double scale) {
  const ChartPlotArea& a = f.area;
  cairo_set_line_width(cr, 1);
  const bool km = f.lengthMeters >= 2000;
  const double unit = km ? 1000 : 1;
  const int maxDistanceTicks = std::max(2, static_cast<int>(a.width / (90 * scale)));
  const double distanceStep = niceStep(f.lengthMeters / unit, maxDistanceTicks);
  cairo_set_font_size(cr, 12 * scale);
  // Height grid lines and labels.
  for (double h = f.heights.low; h <= f.heights.high + f.heights.step / 2; h += f.heights.step) {
    const double y = std::round(f.y(h)) + 0.5;
    setColor(cr, kGrid);
    cairo_move_to(cr, a.left, y);
    cairo_line_to(cr, a.left + a.width, y);
    cairo_stroke(cr);
    setColor(cr, kInk);
    drawText(cr, tickLabel(h, f.heights.step), a.left - 7 * scale, y + 4 * scale, Align::kRight);
  }
  // Distance grid lines and labels.
  for (double d = 0; d <= f.lengthMeters / unit + distanceStep * 1e-6; d += distanceStep) {
    const double x = std::round(f.x(d * unit)) + 0.5;
    setColor(cr, kGrid);
    cairo_move_to(cr, x, a.top);
    cairo_line_to(cr, x, a.top + a.height);
    cairo_stroke(cr);
    setColor(cr, kInk);
    drawText(cr, tickLabel(d, distanceStep), x, a.top + a.height + 17 * scale, Align::kCenter);
  }
  cairo_set_font_size(cr, 12.5 * scale);
  drawText(cr, km ? "distance (km)" : "distance (m)", a.left + a.width / 2,
           a.top + a.height + 36 * scale, Align::kCenter);
  cairo_save(cr);
  cairo_translate(cr, 16 * scale, a.top + a.height / 2);
  cairo_rotate(cr, -std::numbers::pi / 2);
  drawText(cr, "height (m)", 0, 0, Align::kCenter);
  cairo_restore(cr);
}

void drawTerrain(cairo_t* cr, const Frame& f, const std::vector<std::pair<double, double>>& points,
                 double scale) {
  const double bottom = f.area.top + f.area.height;
  cairo_move_to(cr, f.x(points.front().first), bottom);
  for (const auto& [d, h] : points) cairo_line_to(cr, f.x(d), f.y(h));
  cairo_line_to(cr, f.x(points.back().first), bottom);
  cairo_close_path(cr);
  cairo_pattern_t* gradient = cairo_pattern_create_linear(0, f.area.top, 0, bottom);
  cairo_pattern_add_color_stop_rgb(gradient, 0, kTerrainTop.r, kTerrainTop.g, kTerrainTop.b);
  cairo_pattern_add_color_stop_rgb(gradient, 1, kTerrainBottom.r, kTerrainBottom.g,
                                   kTerrainBottom.b);
  cairo_set_source(cr, gradient);
  cairo_fill(cr);
  cairo_pattern_destroy(gradient);
  cairo_new_path(cr);
  for (const auto& [d, h] : points) cairo_line_to(cr, f.x(d), f.y(h));
  setColor(cr, kTerrainLine);
  cairo_set_line_width(cr, 1.5 * scale);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_stroke(cr);
}

void drawFileElevations(cairo_t* cr, const Frame& f,
                        const std::vector<std::pair<double, double>>& points, double scale) {
  cairo_new_path(cr);
  for (const auto& [d, h] : points) {
    if (std::isnan(h)) {
      cairo_new_sub_path(cr);
      continue;
    }
    cairo_line_to(cr, f.x(d), f.y(h));
  }
  setColor(cr, kFileLine);
  cairo_set_line_width(cr, 1.6 * scale);
  cairo_stroke(cr);
}

// A dot on the point and its height beside it, on a pale box so the terrain does not hide it.
void annotate(cairo_t* cr, const Frame& f, double distance, double height, const std::string& text,
              bool above, double scale) {
  const double x = f.x(distance), y = f.y(height);
  setColor(cr, kInk);
  cairo_arc(cr, x, y, 3.2 * scale, 0, 2 * std::numbers::pi);
  cairo_fill(cr);
  cairo_set_font_size(cr, 12 * scale);
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  const double pad = 3 * scale;
  const double tx = std::clamp(x - extents.x_advance / 2, f.area.left + pad,
                               f.area.left + f.area.width - extents.x_advance - pad);
  const double baseline = above ? y - 8 * scale : y + 8 * scale + extents.height;
  cairo_set_source_rgba(cr, 1, 1, 1, 0.8);
  cairo_rectangle(cr, tx - pad, baseline - extents.height - pad, extents.x_advance + 2 * pad,
                  extents.height + 2 * pad);
  cairo_fill(cr);
  setColor(cr, kInk);
  drawText(cr, text, tx, baseline, Align::kLeft);
}

void drawHeaderAndLegend(cairo_t* cr, const Frame& f, double lowest, double highest, bool withFile,
                         int widthPixels, double scale) {
  const double baseline = f.area.top - 14 * scale;
  cairo_select_font_face(cr, kFont, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
  cairo_set_font_size(cr, 13.5 * scale);
  setColor(cr, kInk);
  double x = f.area.left;
  x += drawText(cr, lengthText(f.lengthMeters), x, baseline, Align::kLeft);
  cairo_select_font_face(cr, kFont, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  drawText(cr,
           "  \u00b7  terrain " + groupedInteger(lowest) + " to " + groupedInteger(highest) + " m",
           x, baseline, Align::kLeft);
  // The legend, right-aligned: swatches then labels.
  cairo_set_font_size(cr, 12 * scale);
  const double swatch = 18 * scale, gap = 6 * scale, spacing = 16 * scale;
  double right = widthPixels - 12 * scale;
  const auto entry = [&](const char* label, auto&& drawSwatch) {
    cairo_text_extents_t extents;
    cairo_text_extents(cr, label, &extents);
    const double textLeft = right - extents.x_advance;
    setColor(cr, kInk);
    drawText(cr, label, textLeft, baseline, Align::kLeft);
    drawSwatch(textLeft - gap - swatch, baseline - 4 * scale);
    right = textLeft - gap - swatch - spacing;
  };
  if (withFile) {
    entry("file's elevations", [&](double left, double middle) {
      setColor(cr, kFileLine);
      cairo_set_line_width(cr, 2 * scale);
      cairo_move_to(cr, left, middle);
      cairo_line_to(cr, left + swatch, middle);
      cairo_stroke(cr);
    });
  }
  entry("terrain", [&](double left, double middle) {
    setColor(cr, kTerrainTop);
    cairo_rectangle(cr, left, middle - 5 * scale, swatch, 10 * scale);
    cairo_fill(cr);
    setColor(cr, kTerrainLine);
    cairo_set_line_width(cr, 1.5 * scale);
    cairo_move_to(cr, left, middle - 5 * scale);
    cairo_line_to(cr, left + swatch, middle - 5 * scale);
    cairo_stroke(cr);
  });
}

double terrainHeight(const ProfileRow& r) { return r.heightMeters; }
double fileElevation(const ProfileRow& r) { return r.sample.sourceElevationMeters; }

}  // namespace

ChartPlotArea profileChartPlotArea(int widthPixels, int heightPixels) {
  const double scale = chartScale(widthPixels, heightPixels);
  const double left = 74 * scale, right = 24 * scale, top = 42 * scale, bottom = 48 * scale;
  return {left, top, widthPixels - left - right, heightPixels - top - bottom};
}

Result<formats::ImageRgba> drawProfileChart(const std::vector<ProfileRow>& rows, int widthPixels,
                                            int heightPixels) {
  if (widthPixels < kMinChartWidthPixels || heightPixels < kMinChartHeightPixels ||
      widthPixels > kMaxChartSidePixels || heightPixels > kMaxChartSidePixels) {
    return makeError("a chart of " + std::to_string(widthPixels) + "x" +
                     std::to_string(heightPixels) + " pixels is out of range (" +
                     std::to_string(kMinChartWidthPixels) + "x" +
                     std::to_string(kMinChartHeightPixels) + " to " +
                     std::to_string(kMaxChartSidePixels) + " on a side)");
  }
  if (rows.size() < 2 || !(rows.back().sample.distanceMeters > 0)) {
    return makeError("a profile chart needs a path of two or more distinct points");
  }
  const double scale = chartScale(widthPixels, heightPixels);
  Frame frame;
  frame.area = profileChartPlotArea(widthPixels, heightPixels);
  frame.lengthMeters = rows.back().sample.distanceMeters;
  const int columns = static_cast<int>(frame.area.width * 2);
  const auto terrain = columnExtremes(rows, terrainHeight, frame.lengthMeters, columns);
  const auto file = columnExtremes(rows, fileElevation, frame.lengthMeters, columns);
  const bool withFile =
      std::any_of(file.begin(), file.end(), [](const auto& p) { return !std::isnan(p.second); });
  // The extremes of the terrain (annotated), the axis spanning the file's elevations too.
  const auto [lowestRow, highestRow] = std::minmax_element(
      rows.begin(), rows.end(),
      [](const ProfileRow& a, const ProfileRow& b) { return a.heightMeters < b.heightMeters; });
  double low = lowestRow->heightMeters, high = highestRow->heightMeters;
  for (const auto& [d, h] : file) {
    if (!std::isnan(h)) low = std::min(low, h), high = std::max(high, h);
  }
  // Headroom above the highest point for its label.
  const int maxHeightTicks = std::max(2, static_cast<int>(frame.area.height / (40 * scale)));
  frame.heights = niceAxis(low, high + (high - low) * 0.12, maxHeightTicks, 10);

  std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, widthPixels, heightPixels),
      cairo_surface_destroy);
  std::unique_ptr<cairo_t, decltype(&cairo_destroy)> context(cairo_create(surface.get()),
                                                             cairo_destroy);
  cairo_t* cr = context.get();
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_select_font_face(cr, kFont, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  drawGridAndAxes(cr, frame, scale);
  cairo_save(cr);
  cairo_rectangle(cr, frame.area.left, frame.area.top, frame.area.width, frame.area.height);
  cairo_clip(cr);
  drawTerrain(cr, frame, terrain, scale);
  if (withFile) drawFileElevations(cr, frame, file, scale);
  cairo_restore(cr);
  // The axes over the fill.
  setColor(cr, kInk);
  cairo_set_line_width(cr, 1);
  const double axisX = std::round(frame.area.left) + 0.5;
  const double axisY = std::round(frame.area.top + frame.area.height) + 0.5;
  cairo_move_to(cr, axisX, frame.area.top);
  cairo_line_to(cr, axisX, axisY);
  cairo_line_to(cr, frame.area.left + frame.area.width, axisY);
  cairo_stroke(cr);
  annotate(cr, frame, highestRow->sample.distanceMeters, highestRow->heightMeters,
           "highest " + groupedInteger(highestRow->heightMeters) + " m", true, scale);
  annotate(cr, frame, lowestRow->sample.distanceMeters, lowestRow->heightMeters,
           "lowest " + groupedInteger(lowestRow->heightMeters) + " m",
           frame.y(lowestRow->heightMeters) + 28 * scale > frame.area.top + frame.area.height,
           scale);
  drawHeaderAndLegend(cr, frame, lowestRow->heightMeters, highestRow->heightMeters, withFile,
                      widthPixels, scale);

  cairo_surface_flush(surface.get());
  if (const cairo_status_t status = cairo_status(cr); status != CAIRO_STATUS_SUCCESS) {
    return makeError(std::string("drawing the chart failed: ") + cairo_status_to_string(status));
  }
  // Cairo's RGB24 is a native-endian 0xXXRRGGBB word a pixel.
  formats::ImageRgba image{widthPixels, heightPixels, {}};
  image.pixels.resize(static_cast<size_t>(widthPixels) * static_cast<size_t>(heightPixels) * 4);
  const unsigned char* data = cairo_image_surface_get_data(surface.get());
  const auto stride = static_cast<size_t>(cairo_image_surface_get_stride(surface.get()));
  for (size_t y = 0; y < static_cast<size_t>(heightPixels); ++y) {
    for (size_t x = 0; x < static_cast<size_t>(widthPixels); ++x) {
      uint32_t word = 0;
      std::memcpy(&word, data + y * stride + x * 4, sizeof word);
      uint8_t* out = &image.pixels[(y * static_cast<size_t>(widthPixels) + x) * 4];
      out[0] = static_cast<uint8_t>(word >> 16);
      out[1] = static_cast<uint8_t>(word >> 8);
      out[2] = static_cast<uint8_t>(word);
      out[3] = 255;
    }
  }
  return image;
}

Result<void> writeProfileChartPng(const std::vector<ProfileRow>& rows,
                                  const std::filesystem::path& png, int widthPixels,
                                  int heightPixels) {
  auto image = drawProfileChart(rows, widthPixels, heightPixels);
  if (!image) return makeError(png.string() + ": " + image.error());
  auto bytes = formats::encodePng(*image);
  if (!bytes) return makeError(png.string() + ": encoding the chart failed: " + bytes.error());
  return transport::writeFileAtomically(png, std::span<const std::byte>(*bytes));
}

}  // namespace globe::measure
