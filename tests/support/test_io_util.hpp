// Shared helpers for the io tests: scratch directories, the real DEM data, and GDAL as an oracle.
#pragma once

#include <gdal.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <string>
#include <vector>

#include "tests/support/build_paths.hpp"

namespace globe::testing {

// A fresh directory under the system temp dir, removed with everything in it.
class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            ("globe_io_" + std::string(info ? info->name() : "x") + "_" +
             std::to_string(::getpid()) + "_" + std::to_string(++counter));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

inline void writeText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

inline void writeBytes(const std::filesystem::path& path, size_t size, char fill = 0) {
  std::ofstream(path, std::ios::binary) << std::string(size, fill);
}

// tests/data/dem/<sub> (gtopo30 or original): real elevation kept in the repository, so that a
// clone runs these tests with nothing beside it.
inline std::filesystem::path demDir(const std::string& sub) {
  return std::filesystem::path(GLOBE_SOURCE_DIR) / "tests/data/dem" / sub;
}

// A missing fixture is a failure, never a skip.
#define GLOBE_REQUIRE_DEM_DIR(var, sub)                            \
  const std::filesystem::path var = ::globe::testing::demDir(sub); \
  ASSERT_TRUE(std::filesystem::is_directory(var)) << var << " is missing"

inline const std::vector<std::string>& gtopo30Stems() {
  static const std::vector<std::string> stems = {"W002N52", "ETOPO20", "E138N35_FUJI",
                                                 "N50E008", "N50E009", "N57E011"};
  return stems;
}

// Band 1 of a raster read whole by GDAL (optionally with one named driver), as Int16.
struct GdalRaster {
  bool ok = false;
  std::string driver;
  int cols = 0, rows = 0;
  double geoTransform[6] = {};
  int hasNoData = 0;
  double noData = 0;
  GDALDataType type = GDT_Unknown;
  std::vector<int16_t> heights;
};

inline GdalRaster readWithGdal(const std::filesystem::path& path, const char* driver = nullptr) {
  static std::once_flag once;
  std::call_once(once, [] { GDALAllRegister(); });
  GdalRaster r;
  const char* drivers[] = {driver, nullptr};
  GDALDatasetH ds = GDALOpenEx(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY,
                               driver ? drivers : nullptr, nullptr, nullptr);
  if (!ds) return r;
  r.driver = GDALGetDriverShortName(GDALGetDatasetDriver(ds));
  r.cols = GDALGetRasterXSize(ds);
  r.rows = GDALGetRasterYSize(ds);
  GDALGetGeoTransform(ds, r.geoTransform);
  GDALRasterBandH band = GDALGetRasterBand(ds, 1);
  r.noData = GDALGetRasterNoDataValue(band, &r.hasNoData);
  r.type = GDALGetRasterDataType(band);
  r.heights.resize(static_cast<size_t>(r.cols) * static_cast<size_t>(r.rows));
  r.ok = GDALRasterIO(band, GF_Read, 0, 0, r.cols, r.rows, r.heights.data(), r.cols, r.rows,
                      GDT_Int16, 0, 0) == CE_None;
  GDALClose(ds);
  return r;
}

}  // namespace globe::testing
