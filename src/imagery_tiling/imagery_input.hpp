// What globe-tiler imagery reads: each input (a raster GDAL opens, or a TMS tile tree) described
// once on the main thread: footprint in degrees, resolution and finest level, which bands give
// colour and alpha, and how deep bands are stretched to 8 bits.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/result.hpp"
#include "formats/layer_manifest.hpp"
#include "formats/pyramid_manifest.hpp"

namespace globe::imagery_tiling {

// Linear map of [minimum, maximum] to 0..255 (clamped).
struct ImageryStretch {
  double minimum = 0;
  double maximum = 255;
};

inline constexpr double kFootprintFadePixels = 4.0;

struct ImageryInputOptions {
  // Georeference (EPSG:4326, pixel-is-area) for inputs that have none, e.g. a plate carrée JPEG;
  // an error when every input has its own.
  std::optional<formats::BoundsDegrees> bounds;
  std::vector<int> bands;  // --bands R,G,B[,A]: 1-based, for every raster input; empty: chosen
  std::optional<ImageryStretch> scale;  // --scale MIN,MAX for every band of 16-bit/float inputs
  bool scaleAuto = false;  // --scale auto: each band's 2–98 % percentiles (also the default)
  std::optional<uint32_t> maxLevel;
  bool allowElevation = false;  // --force: one 16-bit or float band drawn as grey, not refused
};

struct ImageryInput {
  enum class Kind { Raster, Tms };
  Kind kind = Kind::Raster;
  std::string argument;  // as given on the command line
  size_t order = 0;      // position on the command line

  // Raster: 1-based GDAL band numbers.
  std::vector<int> colourBands;  // 3 (R, G, B) or 1 (grey, or palette indices)
  int alphaBand = 0;             // 0: validity comes from GDAL's mask band (nodata, masks)
  bool palette = false;
  std::vector<ImageryStretch> stretches;  // one per colour band; empty: 8-bit used as is
  // From --bounds, for an input without georeference.
  std::optional<std::array<double, 6>> assignedGeoTransform;
  std::string assumedSrsWkt;  // a geotransform without a CRS, read as EPSG:4326

  // TMS tree: DIR/<z>/<x>/<y>.<extension>, y counted from the south.
  std::string tmsExtension;
  uint32_t tmsMaxLevel = 0;

  // Where tile pixels sample it: the layer's grid (every input of a layer the same; Edges unless
  // a TMS tree is re-packed, whose tiles are pixel-is-area).
  formats::ImageryPixelGrid pixelGrid = formats::ImageryPixelGrid::Area;
  // Raster edges (x = 0, x = columns, y = 0, y = rows) where the layer's footprint ends: alpha
  // fades to 0 over kFootprintFadePixels source pixels towards them, so the layer blends into
  // what lies under it instead of cutting (chooseFootprintFades).
  std::array<bool, 4> fadeEdges{};
  // Likewise towards the raster's own no-data (an irregular collar around a scene): alpha fades
  // over kFootprintFadePixels source pixels from the nearest transparent one.
  bool fadeCollars = false;

  formats::BoundsDegrees extent;  // after warping to longitude/latitude, within ±180°
  // A footprint across ±180° (a 0..360° image, a scene over the antimeridian): the part beyond,
  // brought onto the globe; the source is read there at longitude + wrapShiftDegrees.
  std::optional<formats::BoundsDegrees> wrappedExtent;
  double wrapShiftDegrees = 0;
  double pixelDegrees = 0;    // after warping
  uint32_t naturalLevel = 0;  // imageryFinestLevel(pixelDegrees)
  uint32_t finestLevel = 0;   // after --max-level
  formats::ImagerySourceInfo info;
  std::vector<std::string> warnings;  // one line each, naming the input
};

// Whether the input's footprint (either part) overlaps the rectangle.
bool overlapsFootprint(const ImageryInput& input, double westDegrees, double southDegrees,
                       double eastDegrees, double northDegrees);

// The level rule: the first level whose texel (tile width / 256) is no larger than the source
// pixel (both in degrees), so the finest tiles never lose the source's detail and oversample it
// by less than 2×.
uint32_t imageryFinestLevel(double pixelDegrees);

// Opens and describes every input; errors name the file and, where an option would fix them,
// the option.
Result<std::vector<ImageryInput>> describeImageryInputs(const std::vector<std::string>& arguments,
                                                        const ImageryInputOptions& options);

}  // namespace globe::imagery_tiling
