// A score for lighting seams along straight pixel columns or rows (tile edges in nadir views):
// per column, the mean absolute brightness step to the next column, divided by the median of
// the same step over the ±12 neighbouring columns; the maximum over all columns and, on the
// transposed image, over all rows. Natural terrain without tile edges scores about 1.2-1.6; a
// faint straight step along a whole column stands out above 2. On images with almost no texture
// (7 km imagery seen from close by) the ratio means little: the excess step, in luma levels of
// 255, says how large the worst line's step is beyond its neighbours'.
#pragma once

#include "formats/image_io.hpp"

namespace globe::bench {

struct SeamScore {
  double score = 0;     // the larger of the two below
  double columns = 0;   // the worst column's ratio
  int worstColumn = 0;  // the step between columns worstColumn and worstColumn + 1
  double rows = 0;
  int worstRow = 0;
  // The largest (line's mean step − the median of its neighbours'), columns and rows alike.
  double excessStepLevels = 0;
};

SeamScore seamScore(const formats::ImageRgba& image);

// The mean luma step (levels of 255) between `column` and the next one, and the median of the
// same step over its 24 neighbouring columns: a known boundary's step against its surroundings.
struct LineStep {
  double stepLevels = 0;
  double neighboursLevels = 0;
};
LineStep columnStep(const formats::ImageRgba& image, int column);

}  // namespace globe::bench
