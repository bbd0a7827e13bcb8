// globe-image-error IMAGE REFERENCE: prints the fraction of pixels beyond a 2 px shift
// (tools/bench_render/image_shift_error.hpp), for the render benchmark's scripts.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>

#include "tools/bench_render/image_shift_error.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Fraction of pixels of IMAGE and REFERENCE that match nothing within a shift."};
  std::string imagePath, referencePath;
  globe::bench::ShiftErrorOptions options;
  app.add_option("IMAGE", imagePath, "PNG")->required();
  app.add_option("REFERENCE", referencePath, "PNG of the same size")->required();
  app.add_option("--shift", options.shiftPixels, "pixels")->capture_default_str();
  app.add_option("--tolerance", options.channelTolerance, "per channel, of 255")
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  auto image = globe::formats::loadImageRgba(imagePath);
  auto reference = globe::formats::loadImageRgba(referencePath);
  if (!image || !reference) {
    std::fprintf(stderr, "globe-image-error: %s\n",
                 (image ? reference.error() : image.error()).c_str());
    return 1;
  }
  auto error = globe::bench::shiftError(*image, *reference, options);
  if (!error) {
    std::fprintf(stderr, "globe-image-error: %s\n", error.error().c_str());
    return 1;
  }
  std::printf("%.6f\t%.6f\t%.6f\n", error->fraction, error->imageUnmatched,
              error->referenceUnmatched);
  return 0;
}
