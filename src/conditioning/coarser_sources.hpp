// What the sources coarser than the one being conditioned say about a point. The tiler answers
// from the already conditioned coarser inputs; tests and benchmarks from a grid of their own.
#pragma once

#include <cstdint>
#include <optional>

namespace globe::conditioning {

class CoarserSources {
 public:
  virtual ~CoarserSources() = default;
  // False when some coarser source covering the point says land there: every sample within a
  // cell of it is land above 0 m. True when none covers the point.
  virtual bool allowSea(double longitudeDegrees, double latitudeDegrees) const = 0;
  // The next coarser source's surface there (bilinear, water at 0 m); nullopt where none covers.
  virtual std::optional<double> heightMeters(double longitudeDegrees,
                                             double latitudeDegrees) const = 0;
  // The same point as a block sample (conditioning/vertex_sample.hpp's rule) saying whether it is
  // water and, where measured, its sea floor; but water only where the surface there (floors where
  // measured, 0 m where not) is at or below 0 m: sea only where the coarser surface says so.
  // nullopt where none covers.
  virtual std::optional<int16_t> sample(double longitudeDegrees, double latitudeDegrees) const = 0;
};

}  // namespace globe::conditioning
