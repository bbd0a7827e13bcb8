// The paper's formula (1), literally; see paper_formula.hpp for why it is kept.
#include "tests/support/paper_formula.hpp"

#include <cmath>

namespace globe::testing {

PaperSphereCoordinates paperFormula1(const glm::dvec3& yUpMeters) {
  const double r =
      std::sqrt(yUpMeters.x * yUpMeters.x + yUpMeters.y * yUpMeters.y + yUpMeters.z * yUpMeters.z);
  return {std::atan(yUpMeters.x / yUpMeters.z), std::asin(yUpMeters.y / r), r};
}

glm::dvec3 ecefToPaperYUp(const glm::dvec3& ecefMeters) {
  return {ecefMeters.y, ecefMeters.z, ecefMeters.x};
}

}  // namespace globe::testing
