#include "imagery_tiling/footprint_fade.hpp"

#include <algorithm>
#include <cmath>

namespace globe::imagery_tiling {
namespace {

constexpr double kEdgeDegrees = 1e-9;

bool overlaps(const formats::BoundsDegrees& a, const formats::BoundsDegrees& b) {
  return a.west < b.east && b.west < a.east && a.south < b.north && b.south < a.north;
}

// Another raster of like resolution (within 2×) reaching within the fade of this one's extent:
// a mosaic, whose members must not fade where they meet.
bool continuedByAnother(const std::vector<ImageryInput>& inputs, size_t i) {
  const ImageryInput& input = inputs[i];
  const double margin = 2.0 * kFootprintFadePixels * input.pixelDegrees;
  const formats::BoundsDegrees grown{input.extent.west - margin, input.extent.south - margin,
                                     input.extent.east + margin, input.extent.north + margin};
  for (size_t j = 0; j < inputs.size(); ++j) {
    const ImageryInput& other = inputs[j];
    if (j == i || other.kind != ImageryInput::Kind::Raster) continue;
    const double ratio = other.pixelDegrees / input.pixelDegrees;
    if (!(ratio >= 0.5 && ratio <= 2.0)) continue;
    if (overlaps(grown, other.extent) ||
        (other.wrappedExtent && overlaps(grown, *other.wrappedExtent))) {
      return true;
    }
  }
  return false;
}

}  // namespace

void chooseFootprintFades(std::vector<ImageryInput>& inputs) {
  for (size_t i = 0; i < inputs.size(); ++i) {
    ImageryInput& input = inputs[i];
    input.fadeEdges = {};
    if (input.kind != ImageryInput::Kind::Raster ||
        input.pixelGrid != formats::ImageryPixelGrid::Edges || !(input.pixelDegrees > 0) ||
        continuedByAnother(inputs, i)) {
      continue;
    }
    const formats::BoundsDegrees& e = input.extent;
    const bool allLongitudes = e.west <= -180.0 + kEdgeDegrees && e.east >= 180.0 - kEdgeDegrees;
    input.fadeEdges = {!allLongitudes, !allLongitudes,
                       e.north<90.0 - kEdgeDegrees, e.south> - 90.0 + kEdgeDegrees};
  }
}

double footprintFade(const ImageryInput& input, double x, double y, int columns, int rows) {
  double distance = kFootprintFadePixels;
  if (input.fadeEdges[0]) distance = std::min(distance, x);
  if (input.fadeEdges[1]) distance = std::min(distance, columns - x);
  if (input.fadeEdges[2]) distance = std::min(distance, y);
  if (input.fadeEdges[3]) distance = std::min(distance, rows - y);
  const double t = std::clamp(distance / kFootprintFadePixels, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

}  // namespace globe::imagery_tiling
