// A grid over the draped shapes' boxes, so that drawing one imagery tile looks at the shapes near
// it, not at all of them: a file of 100,000 parcels drew every tile by testing 100,000 boxes.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "overlays/drape_set.hpp"

namespace globe::overlays {

class DrapeIndex {
 public:
  explicit DrapeIndex(std::span<const DrapedShape> shapes);

  // The indices, ascending (the drawing order), of the shapes whose box may meet `box`: every
  // shape whose box meets it, and perhaps a few more near it (callers test the boxes).
  std::vector<uint32_t> near(const DegreesBox& box) const;

 private:
  DegreesBox bounds_;
  int side_ = 0;  // cells on each side of the grid over bounds_
  double cellWidth_ = 1, cellHeight_ = 1;
  std::vector<std::vector<uint32_t>> cells_;  // row-major
  std::vector<uint32_t> wide_;                // shapes over too many cells, always near
};

}  // namespace globe::overlays
