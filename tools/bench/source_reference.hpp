// The finest source data at a point, for the accuracy mode: the original rasters read whole
// through GDAL (not the project's reader) and sampled bilinearly as the tiler samples them,
// unrounded.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/result.hpp"
#include "rasters/raster_source.hpp"

namespace globe::bench {

class SourceReference {
 public:
  static Result<SourceReference> load(const std::vector<std::filesystem::path>& rasters);
  // The finest raster whose cells cover the point wins (as in the tiler). There: no data at the
  // nearest sample is sea (0 m); otherwise the bilinear mean of the four samples around the
  // point, no-data counted as 0 m. nullopt when no raster covers the point.
  std::optional<double> heightMeters(double longitudeDegrees, double latitudeDegrees) const;

 private:
  struct Raster {
    std::string path;
    geo::SampleGrid grid;  // snapped as the tiler snaps it
    std::vector<int16_t> samples;
    double step = 0;
    int16_t sample(int64_t row, int64_t column) const;
  };
  std::vector<Raster> rasters_;  // finest first
};

}  // namespace globe::bench
