#include "overlays/drape_raster.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

#include "geo/tiling_scheme.hpp"
#include "overlays/drape_index.hpp"

namespace globe::overlays {
namespace {

constexpr double kDegreesPerRadian = 180.0 / M_PI;

struct TileFrame {
  DegreesBox box;
  double pixelsPerDegreeX = 1, pixelsPerDegreeY = 1;
  // Tile pixel of a longitude/latitude; the texel centres lie on the edges (Edges grid).
  double x(double lon) const { return (lon - box.west) * pixelsPerDegreeX + 0.5; }
  double y(double lat) const { return (box.north - lat) * pixelsPerDegreeY + 0.5; }
};

TileFrame frameOf(const geo::TileId& tile, int tileSizePixels) {
  const geo::GlobeRectangle rectangle = geo::GeographicTilingScheme::tileRectangle(tile);
  TileFrame frame;
  frame.box = {
      rectangle.westRadians * kDegreesPerRadian, rectangle.southRadians * kDegreesPerRadian,
      rectangle.eastRadians * kDegreesPerRadian, rectangle.northRadians * kDegreesPerRadian};
  frame.pixelsPerDegreeX = (tileSizePixels - 1) / (frame.box.east - frame.box.west);
  frame.pixelsPerDegreeY = (tileSizePixels - 1) / (frame.box.north - frame.box.south);
  return frame;
}

void setColour(cairo_t* cairo, const Rgba& colour) {
  cairo_set_source_rgba(cairo, colour.r / 255.0, colour.g / 255.0, colour.b / 255.0,
                        colour.a / 255.0);
}

void tracePath(cairo_t* cairo, const TileFrame& frame, const DrapedShape& shape, double shift) {
  cairo_new_path(cairo);
  for (const std::vector<double>& ring : shape.ringsLonLat) {
    for (size_t i = 0; i + 1 < ring.size(); i += 2) {
      const double x = frame.x(ring[i] + shift), y = frame.y(ring[i + 1]);
      if (i == 0) {
        cairo_move_to(cairo, x, y);
      } else {
        cairo_line_to(cairo, x, y);
      }
    }
    if (shape.closed) cairo_close_path(cairo);
  }
}

void drawShape(cairo_t* cairo, const TileFrame& frame, const DrapedShape& shape, double shift) {
  tracePath(cairo, frame, shape, shift);
  if (shape.fill && shape.fillColor.a > 0) {
    setColour(cairo, shape.fillColor);
    cairo_set_fill_rule(cairo, CAIRO_FILL_RULE_EVEN_ODD);
    cairo_fill_preserve(cairo);
  }
  if (shape.outline && shape.lineColor.a > 0 && shape.lineWidthPixels > 0) {
    setColour(cairo, shape.lineColor);
    cairo_set_line_width(cairo, std::max(shape.lineWidthPixels, 1.0));
    cairo_set_line_join(cairo, CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_cap(cairo, CAIRO_LINE_CAP_ROUND);
    cairo_stroke_preserve(cairo);
  }
  cairo_new_path(cairo);
}

// The image's pixel (u, v) goes to lon/lat in its box, rotated about the box's centre, then to
// the tile's pixels: one affine map, so cairo resamples it (bilinear) in one pass.
void drawImage(cairo_t* cairo, const TileFrame& frame, const DrapedImage& image, double shift) {
  cairo_surface_t* source = cairo_image_surface_create_for_data(
      reinterpret_cast<unsigned char*>(const_cast<uint32_t*>(image.premultipliedArgb.data())),
      CAIRO_FORMAT_ARGB32, image.widthPixels, image.heightPixels, image.widthPixels * 4);
  if (cairo_surface_status(source) != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(source);
    return;
  }
  const double centreLon = 0.5 * (image.west + image.east) + shift;
  const double centreLat = 0.5 * (image.south + image.north);
  cairo_save(cairo);
  cairo_translate(cairo, frame.x(centreLon), frame.y(centreLat));
  cairo_scale(cairo, frame.pixelsPerDegreeX, frame.pixelsPerDegreeY);
  // Tile y grows southwards: a counter-clockwise turn on the map is clockwise in these axes.
  cairo_rotate(cairo, -image.rotationDegrees * M_PI / 180.0);
  cairo_translate(cairo, -0.5 * (image.east - image.west), -0.5 * (image.north - image.south));
  cairo_scale(cairo, (image.east - image.west) / image.widthPixels,
              (image.north - image.south) / image.heightPixels);
  cairo_set_source_surface(cairo, source, 0, 0);
  cairo_pattern_set_filter(cairo_get_source(cairo), CAIRO_FILTER_GOOD);
  cairo_pattern_set_extend(cairo_get_source(cairo), CAIRO_EXTEND_PAD);
  cairo_rectangle(cairo, 0, 0, image.widthPixels, image.heightPixels);
  cairo_clip(cairo);
  cairo_paint_with_alpha(cairo, image.opacity);
  cairo_restore(cairo);
  cairo_surface_destroy(source);
}

DegreesBox shifted(const DegreesBox& box, double shift) {
  return {box.west + shift, box.south, box.east + shift, box.north};
}

constexpr double kShifts[] = {0.0, -360.0, 360.0};

// The shapes that may show within `reach` at any of kShifts, in drawing order (ascending).
std::vector<uint32_t> shapesNear(const DrapeSet& set, const DegreesBox& reach) {
  std::vector<uint32_t> near;
  if (!set.shapeIndex) {
    near.resize(set.shapes.size());
    std::iota(near.begin(), near.end(), 0u);
    return near;
  }
  for (const double shift : kShifts) {
    const std::vector<uint32_t> part = set.shapeIndex->near(shifted(reach, -shift));
    near.insert(near.end(), part.begin(), part.end());
  }
  std::sort(near.begin(), near.end());
  near.erase(std::unique(near.begin(), near.end()), near.end());
  return near;
}

}  // namespace

DegreesBox tileReach(const geo::TileId& tile, int tileSizePixels, double maxLineWidthPixels) {
  const TileFrame frame = frameOf(tile, tileSizePixels);
  const double marginPixels = 0.5 * maxLineWidthPixels + 1.5;
  const double marginX = marginPixels / frame.pixelsPerDegreeX;
  const double marginY = marginPixels / frame.pixelsPerDegreeY;
  return {frame.box.west - marginX, frame.box.south - marginY, frame.box.east + marginX,
          frame.box.north + marginY};
}

bool touchesTile(const DrapeSet& set, const geo::TileId& tile, int tileSizePixels) {
  if (set.empty()) return false;
  const DegreesBox reach = tileReach(tile, tileSizePixels, set.widestLinePixels);
  bool anyShift = false;
  for (const double shift : kShifts) anyShift |= shifted(set.bounds, shift).intersects(reach);
  if (!anyShift) return false;
  for (const uint32_t i : shapesNear(set, reach)) {
    for (const double shift : kShifts) {
      if (shifted(set.shapes[i].box, shift).intersects(reach)) return true;
    }
  }
  for (const double shift : kShifts) {
    for (const DrapedImage& image : set.images) {
      if (shifted(image.box, shift).intersects(reach)) return true;
    }
  }
  return false;
}

formats::ImageRgba drawTile(const DrapeSet& set, const geo::TileId& tile, int tileSizePixels) {
  formats::ImageRgba out;
  out.widthPixels = out.heightPixels = tileSizePixels;
  out.pixels.assign(static_cast<size_t>(tileSizePixels) * tileSizePixels * 4, 0);
  const TileFrame frame = frameOf(tile, tileSizePixels);
  const DegreesBox reach = tileReach(tile, tileSizePixels, set.widestLinePixels);

  std::vector<uint32_t> argb(static_cast<size_t>(tileSizePixels) * tileSizePixels, 0);
  cairo_surface_t* surface = cairo_image_surface_create_for_data(
      reinterpret_cast<unsigned char*>(argb.data()), CAIRO_FORMAT_ARGB32, tileSizePixels,
      tileSizePixels, tileSizePixels * 4);
  cairo_t* cairo = cairo_create(surface);
  cairo_set_antialias(cairo, CAIRO_ANTIALIAS_GOOD);
  for (const double shift : kShifts) {
    for (const DrapedImage& image : set.images) {
      if (shifted(image.box, shift).intersects(reach)) drawImage(cairo, frame, image, shift);
    }
  }
  for (const uint32_t i : shapesNear(set, reach)) {
    for (const double shift : kShifts) {
      const DrapedShape& shape = set.shapes[i];
      if (shifted(shape.box, shift).intersects(reach)) drawShape(cairo, frame, shape, shift);
    }
  }
  cairo_destroy(cairo);
  cairo_surface_flush(surface);
  cairo_surface_destroy(surface);

  // Premultiplied native ARGB to straight RGBA, as the imagery layers' textures are.
  for (size_t i = 0; i < argb.size(); ++i) {
    const uint32_t pixel = argb[i];
    const uint32_t a = pixel >> 24;
    if (a == 0) continue;
    const auto straight = [a](uint32_t c) {
      return static_cast<uint8_t>(std::min<uint32_t>(255, (c * 255 + a / 2) / a));
    };
    out.pixels[i * 4 + 0] = straight((pixel >> 16) & 0xff);
    out.pixels[i * 4 + 1] = straight((pixel >> 8) & 0xff);
    out.pixels[i * 4 + 2] = straight(pixel & 0xff);
    out.pixels[i * 4 + 3] = static_cast<uint8_t>(a);
  }
  return out;
}

}  // namespace globe::overlays
