// globe-image-gradient IMAGE...: prints each image's mean luminance gradient magnitude (Rec. 709
// luma, 0..255, central differences over the interior pixels), a measure of how much relief a
// snapshot shows, for tools/bench_render/relief_measure.sh.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "formats/image_io.hpp"

namespace {

double meanGradient(const globe::formats::ImageRgba& image) {
  const int width = image.widthPixels, height = image.heightPixels;
  if (width < 3 || height < 3) return 0.0;
  std::vector<double> luma(static_cast<size_t>(width) * height);
  for (size_t i = 0; i < luma.size(); ++i) {
    const uint8_t* p = &image.pixels[4 * i];
    luma[i] = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
  }
  const auto at = [&](int x, int y) { return luma[static_cast<size_t>(y) * width + x]; };
  double sum = 0.0;
  for (int y = 1; y + 1 < height; ++y) {
    for (int x = 1; x + 1 < width; ++x) {
      const double dx = (at(x + 1, y) - at(x - 1, y)) / 2.0;
      const double dy = (at(x, y + 1) - at(x, y - 1)) / 2.0;
      sum += std::sqrt(dx * dx + dy * dy);
    }
  }
  return sum / (static_cast<double>(width - 2) * (height - 2));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Mean luminance gradient magnitude of each image (one line each)."};
  std::vector<std::string> paths;
  app.add_option("IMAGE", paths, "PNG")->required();
  CLI11_PARSE(app, argc, argv);
  for (const std::string& path : paths) {
    auto image = globe::formats::loadImageRgba(path);
    if (!image) {
      std::fprintf(stderr, "globe-image-gradient: %s\n", image.error().c_str());
      return 1;
    }
    std::printf("%.4f\n", meanGradient(*image));
  }
  return 0;
}
