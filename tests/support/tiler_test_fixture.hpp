// Shared fixture for tiler tests: the bundled real data tiled once per test run, and an
// independent oracle that evaluates the "finest source wins, bilinear" rule on whole rasters.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "formats/pyramid_manifest.hpp"
#include "rasters/raster_source.hpp"

namespace globe::testing {

std::vector<std::string> bundledInputs();  // ETOPO20, W002N52, E138N35_FUJI from data/dem
// Tiles the bundled inputs (once per CTest run: sharedFixture) and returns the pyramid directory.
// Shared by the test processes: copy it before changing it.
const std::filesystem::path& bundledPyramid();
// Tiles the inputs into `out` with the tiler's defaults; failures are test failures.
bool tilePyramidInto(const std::filesystem::path& out, const std::vector<std::string>& inputs);
// Tiles the inputs into a fresh temporary directory (removed at exit); failures are test failures.
std::filesystem::path tilePyramid(const std::string& name, const std::vector<std::string>& inputs);
// Tiles the inputs once per CTest run (sharedFixture, keyed by name and inputs): read-only.
std::filesystem::path sharedPyramid(const std::string& name,
                                    const std::vector<std::string>& inputs);
std::filesystem::path freshTempDir(const std::string& name);
// relative path -> CRC-32 and size of every regular file below dir
std::map<std::string, std::pair<uint32_t, size_t>> checksums(const std::filesystem::path& dir);

// Whole-raster reference sampler, written separately from the tiler's strip sampler.
class Oracle {
 public:
  explicit Oracle(const std::vector<std::string>& inputs);
  int16_t height(double longitudeDegrees, double latitudeDegrees) const;

 private:
  struct Raster {
    geo::SampleGrid grid;
    std::vector<int16_t> samples;
    double step;
    formats::BoundsDegrees extent;  // as the tiler snapped it
    double margin = 0;              // the bend margin the conditioning chose
    int16_t sample(int64_t row, int64_t column) const;
  };
  // The vertex one raster gives at a point (clamped to its edge outside it).
  int16_t rasterHeight(const Raster& r, double lon, double lat) const;
  // The finer raster's edge height the ground outside it bends to.
  double edgeMeters(const Raster& r, double lon, double lat) const;
  std::vector<Raster> rasters_;  // finest first
};

}  // namespace globe::testing
