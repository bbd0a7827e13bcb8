#include "imagery_tiling/imagery_bands.hpp"

#include <cpl_conv.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string_view>
#include <vector>

#include "core/ascii_case.hpp"

namespace globe::imagery_tiling {
namespace {

std::string bandsGdalError() {
  const char* message = CPLGetLastErrorMsg();
  return message != nullptr && *message != '\0' ? message : "unknown GDAL error";
}

std::string formatStretchBound(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", value);
  return text;
}

// The fraction-th sample of a histogram whose bucket i holds values around first + i * step.
double percentile(const std::vector<GUIntBig>& histogram, double first, double step,
                  double fraction) {
  GUIntBig total = 0;
  for (GUIntBig count : histogram) total += count;
  GUIntBig seen = 0;
  for (size_t i = 0; i < histogram.size(); ++i) {
    seen += histogram[i];
    if (static_cast<double>(seen) >= fraction * static_cast<double>(total)) {
      return first + static_cast<double>(i) * step;
    }
  }
  return first + static_cast<double>(histogram.size() - 1) * step;
}

// The band's 2 % and 98 % percentiles from an exact histogram of the whole band (its nodata
// value excluded): one bucket per value for integers up to 16 bits (one pass, exact), else 4096
// buckets between the band's minimum and maximum.
Result<ImageryStretch> percentileStretch(GDALRasterBandH band, const std::string& name) {
  double first = 0, step = 1;
  int buckets = 0;
  switch (GDALGetRasterDataType(band)) {
    case GDT_Byte:
      buckets = 256;
      break;
    case GDT_UInt16:
      buckets = 65536;
      break;
    case GDT_Int16:
      first = -32768;
      buckets = 65536;
      break;
    default: {
      double range[2] = {0, 0};
      if (GDALComputeRasterMinMax(band, FALSE, range) != CE_None) {
        return makeError(name + ": cannot compute band " + std::to_string(GDALGetBandNumber(band)) +
                         "'s range for its 2-98 % stretch: " + bandsGdalError());
      }
      if (range[1] <= range[0]) return ImageryStretch{range[0], range[0] + 1};
      buckets = 4096;
      first = range[0];
      step = (range[1] - range[0]) / (buckets - 1);
    }
  }
  // Counted here, row by row, not by GDALGetRasterHistogram: that one caches the histogram in
  // the input's .aux.xml, and the tiler must never write beside its inputs.
  std::vector<GUIntBig> histogram(static_cast<size_t>(buckets));
  const int cols = GDALGetRasterBandXSize(band), rows = GDALGetRasterBandYSize(band);
  int hasNoData = 0;
  const double noData = GDALGetRasterNoDataValue(band, &hasNoData);
  std::vector<double> row(static_cast<size_t>(cols));
  for (int r = 0; r < rows; ++r) {
    if (GDALRasterIO(band, GF_Read, 0, r, cols, 1, row.data(), cols, 1, GDT_Float64, 0, 0) !=
        CE_None) {
      return makeError(name + ": cannot read band " + std::to_string(GDALGetBandNumber(band)) +
                       " for its 2-98 % stretch: " + bandsGdalError());
    }
    for (const double value : row) {
      if (!std::isfinite(value) || (hasNoData != 0 && value == noData)) continue;
      const double bucket = std::round((value - first) / step);
      if (bucket < 0 || bucket >= buckets) continue;
      ++histogram[static_cast<size_t>(bucket)];
    }
  }
  ImageryStretch stretch{percentile(histogram, first, step, 0.02),
                         percentile(histogram, first, step, 0.98)};
  if (stretch.maximum <= stretch.minimum) stretch.maximum = stretch.minimum + 1;
  return stretch;
}

Result<void> chooseStretches(GDALDatasetH dataset, const std::string& name,
                             const ImageryInputOptions& options, ImageryInput& input) {
  bool deep = false;
  for (int b : input.colourBands) {
    deep = deep || GDALGetRasterDataType(GDALGetRasterBand(dataset, b)) != GDT_Byte;
  }
  if (input.palette || !deep) {
    if (options.scale || options.scaleAuto) input.info.stretch = "none (8-bit input)";
    return {};
  }
  if (options.scale) {
    input.stretches.assign(input.colourBands.size(), *options.scale);
    input.info.stretch = "linear " + formatStretchBound(options.scale->minimum) + ".." +
                         formatStretchBound(options.scale->maximum) + " to 0..255";
    return {};
  }
  input.info.stretch = "2-98% per band:";
  for (int b : input.colourBands) {
    auto stretch = percentileStretch(GDALGetRasterBand(dataset, b), name);
    if (!stretch) return Error{stretch.error()};
    input.stretches.push_back(*stretch);
    input.info.stretch +=
        " " + formatStretchBound(stretch->minimum) + ".." + formatStretchBound(stretch->maximum);
  }
  return {};
}

}  // namespace

std::string bandList(const std::vector<int>& bands) {
  std::string text;
  for (int b : bands) text += (text.empty() ? "" : ",") + std::to_string(b);
  return text;
}

// Heights in a band: a unit of length, or signed samples (Int16 as SRTM and GTOPO30, Float32 as
// Copernicus): an image's digital numbers are unsigned (Landsat's and Sentinel-2's UInt16).
bool holdsHeights(GDALRasterBandH band) {
  static constexpr std::string_view kLengthUnits[] = {"m",  "metre", "metres", "meter", "meters",
                                                      "ft", "foot",  "feet",   "us-ft"};
  const char* unitType = GDALGetRasterUnitType(band);
  const std::string unit = core::asciiLower(unitType != nullptr ? unitType : "");
  const GDALDataType type = GDALGetRasterDataType(band);
  return std::find(std::begin(kLengthUnits), std::end(kLengthUnits), unit) !=
             std::end(kLengthUnits) ||
         GDALDataTypeIsSigned(type) != 0;
}

// One band deeper than 8 bits without colour is how an elevation model looks: refused when its
// samples are heights (holdsHeights), drawn with a loud warning when they may be an image's
// (one unsigned 16-bit band: a Landsat band, or a DEM stored unsigned).
Result<void> checkNotElevation(GDALDatasetH dataset, int bandNumber, const std::string& name,
                               ImageryInput& input) {
  GDALRasterBandH band = GDALGetRasterBand(dataset, bandNumber);
  const GDALDataType type = GDALGetRasterDataType(band);
  if (type == GDT_Byte) return {};
  const std::string tileElevation = "tile elevation with `globe-tiler -o PYRAMID " + name + "`";
  if (holdsHeights(band)) {
    return makeError(name + ": one band of " + GDALGetDataTypeName(type) +
                     " samples without colour, as an elevation model has; " + tileElevation +
                     ", or add --force to draw it as grey imagery");
  }
  input.warnings.push_back(name + ": one band of " + GDALGetDataTypeName(type) +
                           " samples without colour: drawn as grey imagery; if they are heights, "
                           "it is an elevation model: " +
                           tileElevation);
  return {};
}

Result<void> chooseImageryBands(GDALDatasetH dataset, const std::string& name,
                                const ImageryInputOptions& options, ImageryInput& input) {
  const int count = GDALGetRasterCount(dataset);
  if (count < 1) return makeError(name + ": has no raster bands");
  const std::string countText = std::to_string(count) + (count == 1 ? " band" : " bands");
  int red = 0, green = 0, blue = 0, alpha = 0;
  std::vector<int> notAlpha;
  for (int b = 1; b <= count; ++b) {
    const GDALColorInterp interpretation =
        GDALGetRasterColorInterpretation(GDALGetRasterBand(dataset, b));
    int* slot = interpretation == GCI_RedBand     ? &red
                : interpretation == GCI_GreenBand ? &green
                : interpretation == GCI_BlueBand  ? &blue
                : interpretation == GCI_AlphaBand ? &alpha
                                                  : nullptr;
    if (slot != nullptr && *slot == 0) *slot = b;
    if (interpretation != GCI_AlphaBand) notAlpha.push_back(b);
  }
  GDALRasterBandH first = GDALGetRasterBand(dataset, 1);
  std::string bands;
  if (!options.bands.empty()) {
    for (int b : options.bands) {
      if (b < 1 || b > count) {
        return makeError(name + ": --bands " + bandList(options.bands) + " names band " +
                         std::to_string(b) + ", but it has " + countText);
      }
    }
    input.colourBands.assign(options.bands.begin(), options.bands.begin() + 3);
    // Without an A, a band GDAL calls alpha stays alpha unless it was chosen as a colour.
    const bool alphaIsColour = std::find(input.colourBands.begin(), input.colourBands.end(),
                                         alpha) != input.colourBands.end();
    input.alphaBand = options.bands.size() == 4 ? options.bands[3] : alphaIsColour ? 0 : alpha;
    bands = "bands " + bandList(input.colourBands) + " as RGB (--bands)";
  } else if (red != 0 && green != 0 && blue != 0) {
    input.colourBands = {red, green, blue};
    input.alphaBand = alpha;
    bands = red == 1 && green == 2 && blue == 3
                ? "RGB"
                : "RGB (bands " + bandList({red, green, blue}) + ")";
  } else if (GDALGetRasterColorInterpretation(first) == GCI_PaletteIndex &&
             GDALGetRasterColorTable(first) != nullptr) {
    input.colourBands = {1};
    input.palette = true;
    input.alphaBand = alpha;
    bands = "palette";
  } else if (notAlpha.empty()) {
    return makeError(name + ": every band is alpha; choose colour bands with --bands R,G,B");
  } else {
    const bool grey = notAlpha.size() < 3;
    if (grey && !options.allowElevation) {
      if (auto checked = checkNotElevation(dataset, notAlpha[0], name, input); !checked)
        return checked;
    }
    input.alphaBand = alpha;
    input.colourBands.assign(notAlpha.begin(), notAlpha.begin() + (grey ? 1 : 3));
    // GDAL's convention for three bands without interpretation (JPEG, NAIP's gray, undefined...);
    // beyond what is drawn, nothing says which bands are the colours: a guess the user must hear.
    bands = !grey ? "bands " + bandList(input.colourBands) + " as RGB"
            : input.colourBands[0] == 1
                ? "grey"
                : "grey (band " + std::to_string(input.colourBands[0]) + ")";
    if (notAlpha.size() > input.colourBands.size()) {
      input.warnings.push_back(
          name + ": " + countText + " without red/green/blue interpretation; drawing " +
          (grey ? "band " + bandList(input.colourBands) + " as grey"
                : "bands " + bandList(input.colourBands) + " as red,green,blue") +
          " (choose with --bands R,G,B)");
    }
  }
  if (input.alphaBand != 0) {
    bands += " + alpha (band " + std::to_string(input.alphaBand) + ")";
  } else {
    const int flags = GDALGetMaskFlags(GDALGetRasterBand(dataset, input.colourBands[0]));
    if ((flags & GMF_ALL_VALID) == 0) {
      bands += (flags & GMF_NODATA) != 0 ? ", nodata transparent" : ", mask transparent";
    }
  }
  std::vector<int> used = input.colourBands;
  if (input.alphaBand != 0) used.push_back(input.alphaBand);
  std::sort(used.begin(), used.end());
  if (count > std::unique(used.begin(), used.end()) - used.begin()) {
    bands +=
        input.alphaBand != 0 ? " (other bands unused)" : " (other bands unused, none is alpha)";
  }
  input.info.bands = bands;
  return chooseStretches(dataset, name, options, input);
}

}  // namespace globe::imagery_tiling
