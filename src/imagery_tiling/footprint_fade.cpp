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
    input.fadeCollars = false;
    if (input.kind != ImageryInput::Kind::Raster ||
        input.pixelGrid != formats::ImageryPixelGrid::Edges || !(input.pixelDegrees > 0) ||
        continuedByAnother(inputs, i)) {
      continue;
    }
    const formats::BoundsDegrees& e = input.extent;
    const bool allLongitudes = e.west <= -180.0 + kEdgeDegrees && e.east >= 180.0 - kEdgeDegrees;
    input.fadeCollars = true;
    input.fadeEdges = {!allLongitudes, !allLongitudes,
                       e.north<90.0 - kEdgeDegrees, e.south> - 90.0 + kEdgeDegrees};
  }
}

double smoothFade(double distancePixels) {
  const double t = std::clamp(distancePixels / kFootprintFadePixels, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

void distanceToTransparent(const std::vector<uint8_t>& rgba, int width, int height,
                           std::vector<float>& distance) {
  // Two passes of the 3-4 chamfer metric (within 8 % of Euclidean), in thirds of a pixel.
  constexpr int kFar = 1 << 20;
  std::vector<int> d(static_cast<size_t>(width) * height);
  for (size_t i = 0; i < d.size(); ++i) d[i] = rgba[i * 4 + 3] == 0 ? 0 : kFar;
  auto at = [&](int x, int y) -> int& { return d[static_cast<size_t>(y) * width + x]; };
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      int& v = at(x, y);
      if (x > 0) v = std::min(v, at(x - 1, y) + 3);
      if (y > 0) {
        v = std::min(v, at(x, y - 1) + 3);
        if (x > 0) v = std::min(v, at(x - 1, y - 1) + 4);
        if (x + 1 < width) v = std::min(v, at(x + 1, y - 1) + 4);
      }
    }
  }
  for (int y = height - 1; y >= 0; --y) {
    for (int x = width - 1; x >= 0; --x) {
      int& v = at(x, y);
      if (x + 1 < width) v = std::min(v, at(x + 1, y) + 3);
      if (y + 1 < height) {
        v = std::min(v, at(x, y + 1) + 3);
        if (x + 1 < width) v = std::min(v, at(x + 1, y + 1) + 4);
        if (x > 0) v = std::min(v, at(x - 1, y + 1) + 4);
      }
    }
  }
  distance.resize(d.size());
  for (size_t i = 0; i < d.size(); ++i) distance[i] = static_cast<float>(d[i]) / 3.0f;
}

double footprintFade(const ImageryInput& input, double x, double y, int columns, int rows) {
  double distance = kFootprintFadePixels;
  if (input.fadeEdges[0]) distance = std::min(distance, x);
  if (input.fadeEdges[1]) distance = std::min(distance, columns - x);
  if (input.fadeEdges[2]) distance = std::min(distance, y);
  if (input.fadeEdges[3]) distance = std::min(distance, rows - y);
  return smoothFade(distance);
}

}  // namespace globe::imagery_tiling
