#include "geo/sample_grid.hpp"

namespace globe::geo {

double SampleGrid::westDegrees() const {
  return wrapsLongitude ? -180.0 : firstColumnLongitudeDegrees - columnStepDegrees / 2;
}
double SampleGrid::eastDegrees() const {
  return wrapsLongitude
             ? 180.0
             : firstColumnLongitudeDegrees + (static_cast<double>(cols) - 0.5) * columnStepDegrees;
}
double SampleGrid::northDegrees() const { return firstRowLatitudeDegrees + rowStepDegrees / 2; }
double SampleGrid::southDegrees() const {
  return firstRowLatitudeDegrees - (static_cast<double>(rows) - 0.5) * rowStepDegrees;
}

}  // namespace globe::geo
