#include "tests/tools/fidelity/real_input_cases.hpp"

#include <cpl_string.h>
#include <gdal.h>
#include <gdal_utils.h>
#include <gtest/gtest.h>

#include <vector>

namespace globe::fidelity::testing {
namespace {

// Runs one of GDAL's utilities on `input` with its command-line arguments.
template <typename MakeOptions, typename Run>
void runUtility(const std::string& input, const std::filesystem::path& output,
                std::vector<std::string> arguments, MakeOptions makeOptions, Run run) {
  GDALAllRegister();
  GDALDatasetH source = GDALOpen(input.c_str(), GA_ReadOnly);
  ASSERT_NE(source, nullptr) << input;
  std::vector<char*> argv;
  for (std::string& a : arguments) argv.push_back(a.data());
  argv.push_back(nullptr);
  auto* options = makeOptions(argv.data(), nullptr);
  ASSERT_NE(options, nullptr);
  int failed = 0;
  GDALDatasetH made = run(output.c_str(), source, options, &failed);
  ASSERT_NE(made, nullptr) << CPLGetLastErrorMsg();
  EXPECT_EQ(failed, 0);
  GDALClose(made);
  GDALClose(source);
}

}  // namespace

void cropRaster(const std::string& input, const std::filesystem::path& output, double west,
                double south, double east, double north) {
  runUtility(input, output,
             {"-of", "GTiff", "-projwin", std::to_string(west), std::to_string(north),
              std::to_string(east), std::to_string(south)},
             GDALTranslateOptionsNew,
             [](const char* out, GDALDatasetH in, GDALTranslateOptions* o, int* failed) {
               GDALDatasetH made = GDALTranslate(out, in, o, failed);
               GDALTranslateOptionsFree(o);
               return made;
             });
}

void warpRaster(const std::string& input, const std::filesystem::path& output,
                const std::string& crs, double metres) {
  runUtility(input, output,
             {"-of", "GTiff", "-t_srs", crs, "-tr", std::to_string(metres), std::to_string(metres),
              "-r", "bilinear", "-dstnodata", "-32768"},
             GDALWarpAppOptionsNew,
             [](const char* out, GDALDatasetH in, GDALWarpAppOptions* o, int* failed) {
               GDALDatasetH made = GDALWarp(out, nullptr, 1, &in, o, failed);
               GDALWarpAppOptionsFree(o);
               return made;
             });
}

void blankRaster(const std::string& input, const std::filesystem::path& output,
                 const std::function<bool(double, double)>& blank) {
  GDALAllRegister();
  GDALDatasetH source = GDALOpen(input.c_str(), GA_ReadOnly);
  ASSERT_NE(source, nullptr) << input;
  const int cols = GDALGetRasterXSize(source), rows = GDALGetRasterYSize(source);
  double gt[6];
  ASSERT_EQ(GDALGetGeoTransform(source, gt), CE_None) << input;
  GDALRasterBandH in = GDALGetRasterBand(source, 1);
  int hasNoData = 0;
  const double noData = GDALGetRasterNoDataValue(in, &hasNoData);
  std::vector<int16_t> samples(static_cast<size_t>(cols) * static_cast<size_t>(rows));
  ASSERT_EQ(
      GDALRasterIO(in, GF_Read, 0, 0, cols, rows, samples.data(), cols, rows, GDT_Int16, 0, 0),
      CE_None);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      int16_t& s =
          samples[static_cast<size_t>(r) * static_cast<size_t>(cols) + static_cast<size_t>(c)];
      if (hasNoData && s == static_cast<int16_t>(noData)) s = -32768;
      if (blank(gt[0] + (c + 0.5) * gt[1], gt[3] + (r + 0.5) * gt[5])) s = -32768;
    }
  }
  GDALDatasetH out =
      GDALCreate(GDALGetDriverByName("GTiff"), output.c_str(), cols, rows, 1, GDT_Int16, nullptr);
  ASSERT_NE(out, nullptr) << output;
  GDALSetGeoTransform(out, gt);
  GDALSetProjection(out, GDALGetProjectionRef(source));
  GDALRasterBandH band = GDALGetRasterBand(out, 1);
  GDALSetRasterNoDataValue(band, -32768);
  ASSERT_EQ(
      GDALRasterIO(band, GF_Write, 0, 0, cols, rows, samples.data(), cols, rows, GDT_Int16, 0, 0),
      CE_None);
  GDALClose(out);
  GDALClose(source);
}

}  // namespace globe::fidelity::testing
