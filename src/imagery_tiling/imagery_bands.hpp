// Which bands of a raster draw red, green, blue and alpha, and how bands deeper than 8 bits reach
// 0..255. The rules (also in `globe-tiler imagery --help`):
// - --bands R,G,B[,A] when given; else GDAL's colour interpretation (red, green, blue in any band
//   order; a palette expanded; one band grey); else the first three bands that are not alpha, with
//   a warning when that leaves bands out, since nothing says they are red, green and blue.
// - Alpha: a band GDAL calls alpha (or the A of --bands); without one, no data and masks.
// - 8-bit bands are drawn as they are; deeper ones (16-bit, float) are stretched per band from its
//   2nd to its 98th percentile, or by --scale MIN,MAX for every band.
#pragma once

#include <gdal.h>

#include <string>

#include "core/result.hpp"
#include "imagery_tiling/imagery_input.hpp"

namespace globe::imagery_tiling {

// Sets input.colourBands, alphaBand, palette, stretches, info.bands, info.stretch and warnings;
// errors name the file.
Result<void> chooseImageryBands(GDALDatasetH dataset, const std::string& name,
                                const ImageryInputOptions& options, ImageryInput& input);

// "1,2,3" for band numbers.
std::string bandList(const std::vector<int>& bands);

}  // namespace globe::imagery_tiling
