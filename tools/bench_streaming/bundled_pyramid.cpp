#include "bundled_pyramid.hpp"

#include <cstdio>
#include <string>

#include "tests/support/build_paths.hpp"
#include "tiling/tiler.hpp"

namespace globe::bench {

Result<std::filesystem::path> tileBundledPyramid(const std::filesystem::path& scratch) {
  std::filesystem::remove_all(scratch);
  const std::string dem = std::string(GLOBE_SOURCE_DIR) + "/data/dem/";
  tiling::TilerOptions options;
  options.inputs = {dem + "ETOPO20.DEM", dem + "W002N52.DEM", dem + "E138N35_FUJI.DEM"};
  options.outputDir = scratch / "pyramid";
  auto report = tiling::runTiler(options);
  if (!report) return Error{report.error()};
  return options.outputDir;
}

std::shared_ptr<transport::Network> defaultNetwork() {
  return std::make_shared<transport::Network>(
      transport::NetworkSettings{},
      [](const std::string& warning) { std::fprintf(stderr, "globe: %s\n", warning.c_str()); });
}

}  // namespace globe::bench
