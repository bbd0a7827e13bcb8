// globe-image-seams IMAGE...: per image, the seam score (tools/bench_render/seam_score.hpp: the
// worst column's or row's step over its neighbours' median) and the worst excess step in luma
// levels, tab-separated; with --column, also that column's step and its neighbours' median, for
// tools/bench_render/seam_measure.sh.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>
#include <vector>

#include "formats/image_io.hpp"
#include "tools/bench_render/seam_score.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Seam score and excess step (luma levels) of each image, one line each."};
  std::vector<std::string> paths;
  int column = -1;
  app.add_option("IMAGE", paths, "PNG")->required();
  app.add_option(
      "--column", column,
      "also print the step between this column and the next, and its neighbours' median");
  CLI11_PARSE(app, argc, argv);
  for (const std::string& path : paths) {
    auto image = globe::formats::loadImageRgba(path);
    if (!image) {
      std::fprintf(stderr, "globe-image-seams: %s\n", image.error().c_str());
      return 1;
    }
    const globe::bench::SeamScore s = globe::bench::seamScore(*image);
    if (column >= 0) {
      const globe::bench::LineStep step = globe::bench::columnStep(*image, column);
      std::printf("%.3f\t%.3f\t%.3f\t%.3f\n", s.score, s.excessStepLevels, step.stepLevels,
                  step.neighboursLevels);
    } else {
      std::printf("%.3f\t%.3f\n", s.score, s.excessStepLevels);
    }
  }
  return 0;
}
