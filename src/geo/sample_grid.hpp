// A raster's grid in geographic degrees: where its sample centres lie, rows from the north. The
// one grid type: rasters' readers describe their files with it, and conditioning's in-memory
// DemGrid is one with its samples.
#pragma once

#include <cstddef>
#include <cstdint>

namespace globe::geo {

struct SampleGrid {
  int64_t cols = 0, rows = 0;
  double firstColumnLongitudeDegrees = 0;  // centre of column 0
  double firstRowLatitudeDegrees = 0;      // centre of row 0 (northernmost)
  double columnStepDegrees = 0;            // > 0, eastwards
  double rowStepDegrees = 0;               // > 0, southwards
  bool wrapsLongitude = false;  // cols*columnStep >= 360 - tiny: the source covers every longitude

  // Closed extent covered by the cells (sample centre ± half a step), in degrees; for wrapping
  // grids west=-180, east=180.
  double westDegrees() const;
  double eastDegrees() const;
  double southDegrees() const;
  double northDegrees() const;

  // Sample centres.
  double longitudeDegrees(int64_t column) const {
    return firstColumnLongitudeDegrees + static_cast<double>(column) * columnStepDegrees;
  }
  double latitudeDegrees(int64_t row) const {
    return firstRowLatitudeDegrees - static_cast<double>(row) * rowStepDegrees;
  }
  // Row-major position of a sample.
  size_t index(int64_t row, int64_t column) const {
    return static_cast<size_t>(row) * static_cast<size_t>(cols) + static_cast<size_t>(column);
  }
};

}  // namespace globe::geo
