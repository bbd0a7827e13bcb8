// The GDAL RasterSource: band 1 of any raster GDAL opens, warped to WGS84 degrees when projected,
// in metres by the band's unit type, scale and offset.
#include <cpl_conv.h>
#include <cpl_string.h>
#include <gdal.h>
#include <gdalwarper.h>
#include <ogr_srs_api.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <vector>

#include "rasters/gtopo30_header.hpp"
#include "rasters/raster_source.hpp"

namespace globe::rasters {
namespace {

void registerGdalOnce() {
  static std::once_flag once;
  std::call_once(once, [] { GDALAllRegister(); });
}

// Keeps GDAL off stderr on this thread (its handler stack is per thread) and turns its last
// message into ours.
class QuietGdal {
 public:
  QuietGdal() {
    CPLPushErrorHandler(CPLQuietErrorHandler);
    CPLErrorReset();
  }
  QuietGdal(const QuietGdal&) = delete;
  QuietGdal& operator=(const QuietGdal&) = delete;
  ~QuietGdal() { CPLPopErrorHandler(); }
  static std::string message() {
    const char* m = CPLGetLastErrorMsg();
    return m && *m ? m : "GDAL gave no reason";
  }
};

struct DatasetCloser {
  void operator()(void* ds) const {
    if (ds) GDALClose(static_cast<GDALDatasetH>(ds));
  }
};
using DatasetPtr = std::unique_ptr<void, DatasetCloser>;

struct OsrDeleter {
  void operator()(void* srs) const {
    if (srs) OSRDestroySpatialReference(static_cast<OGRSpatialReferenceH>(srs));
  }
};

bool isDegrees(OGRSpatialReferenceH srs) {
  constexpr double kDegreeRadians = 0.017453292519943295;
  return OSRIsGeographic(srs) &&
         std::abs(OSRGetAngularUnits(srs, nullptr) - kDegreeRadians) < 1e-12;
}

// Without a CRS, accept the geotransform as degrees when the extent fits the globe (netCDF files
// such as etopo20.cdf carry lon/lat axes but no CRS; their longitudes may run to 380).
bool plausiblyDegrees(const double gt[6], int cols, int rows) {
  const double x0 = gt[0], x1 = gt[0] + cols * gt[1];
  const double y0 = gt[3], y1 = gt[3] + rows * gt[5];
  const double slackY = std::abs(gt[5]) + 1e-9;
  return std::min(x0, x1) >= -360.0 && std::max(x0, x1) <= 720.0 &&
         std::min(y0, y1) >= -90.0 - slackY && std::max(y0, y1) <= 90.0 + slackY &&
         std::abs(gt[1]) <= 360.0;
}

// A value the warper can write outside the source footprint, when the source has no no-data.
double fillValueFor(GDALDataType type) {
  switch (type) {
    case GDT_Byte:
      return 255;
    case GDT_UInt16:
      return 65535;
    case GDT_UInt32:
      return 4294967295.0;
    case GDT_Int16:
      return -32768;
    case GDT_Int32:
      return std::numeric_limits<int32_t>::min();
    default:
      return std::numeric_limits<double>::quiet_NaN();
  }
}

// Bilinear warp of band 1 to WGS84 longitude/latitude (what GDALAutoCreateWarpedVRT does, plus
// no-data so that cells outside the source read as no-data rather than 0 m).
Result<DatasetPtr> warpToWgs84(GDALDatasetH source, const std::string& path) {
  std::unique_ptr<void, OsrDeleter> wgs84(OSRNewSpatialReference(nullptr));
  OSRSetWellKnownGeogCS(static_cast<OGRSpatialReferenceH>(wgs84.get()), "WGS84");
  char* wkt = nullptr;
  OSRExportToWkt(static_cast<OGRSpatialReferenceH>(wgs84.get()), &wkt);
  void* transformer = GDALCreateGenImgProjTransformer(source, nullptr, nullptr, wkt, TRUE, 0, 0);
  if (!transformer) {
    CPLFree(wkt);
    return makeError(path + ": cannot transform its coordinates to WGS84: " + QuietGdal::message());
  }
  double gt[6];
  int cols = 0, rows = 0;
  if (GDALSuggestedWarpOutput(source, GDALGenImgProjTransform, transformer, gt, &cols, &rows) !=
      CE_None) {
    GDALDestroyGenImgProjTransformer(transformer);
    CPLFree(wkt);
    return makeError(path + ": cannot find its extent in WGS84: " + QuietGdal::message());
  }
  GDALSetGenImgProjTransformerDstGeoTransform(transformer, gt);

  GDALRasterBandH band = GDALGetRasterBand(source, 1);
  int hasNoData = 0;
  const double noData = GDALGetRasterNoDataValue(band, &hasNoData);
  GDALWarpOptions* options = GDALCreateWarpOptions();
  options->eResampleAlg = GRA_Bilinear;
  options->hSrcDS = source;
  options->nBandCount = 1;
  options->panSrcBands = static_cast<int*>(CPLMalloc(sizeof(int)));
  options->panDstBands = static_cast<int*>(CPLMalloc(sizeof(int)));
  options->panSrcBands[0] = options->panDstBands[0] = 1;
  if (hasNoData) {
    options->padfSrcNoDataReal = static_cast<double*>(CPLMalloc(sizeof(double)));
    options->padfSrcNoDataReal[0] = noData;
  }
  options->padfDstNoDataReal = static_cast<double*>(CPLMalloc(sizeof(double)));
  options->padfDstNoDataReal[0] = hasNoData ? noData : fillValueFor(GDALGetRasterDataType(band));
  options->papszWarpOptions = CSLSetNameValue(options->papszWarpOptions, "INIT_DEST", "NO_DATA");
  options->pfnTransformer = GDALGenImgProjTransform;
  options->pTransformerArg = transformer;  // the VRT destroys it
  GDALDatasetH warped = GDALCreateWarpedVRT(source, cols, rows, gt, options);
  const double dstNoData = options->padfDstNoDataReal[0];
  GDALDestroyWarpOptions(options);
  if (!warped) {
    CPLFree(wkt);  // the transformer may already be gone with the failed VRT: leak, not free twice
    return makeError(path + ": cannot warp it to WGS84: " + QuietGdal::message());
  }
  GDALSetProjection(warped, wkt);
  CPLFree(wkt);
  GDALSetRasterNoDataValue(GDALGetRasterBand(warped, 1), dstNoData);
  return DatasetPtr(warped);
}

class GdalSource final : public detail::ColumnMappedSource {
 public:
  GdalSource(std::string path, const geo::SampleGrid& grid, DatasetPtr source, DatasetPtr warped,
             bool flipRows, std::string driver, formats::VerticalUnits vertical)
      : ColumnMappedSource(std::move(path), grid, std::move(vertical)),
        source_(std::move(source)),
        warped_(std::move(warped)),
        driver_(std::move(driver)),
        rows_(grid.rows),
        flipRows_(flipRows) {
    band_ = GDALGetRasterBand(warped_ ? warped_.get() : source_.get(), 1);
    noData_ = GDALGetRasterNoDataValue(band_, &hasNoData_);
    // Float32 data holds the no-data value rounded to float (netCDF's -1e34 is -9.99999979e33).
    if (hasNoData_ && GDALGetRasterDataType(band_) == GDT_Float32 && std::isfinite(noData_) &&
        std::abs(noData_) <= std::numeric_limits<float>::max()) {
      noData_ = static_cast<double>(static_cast<float>(noData_));
    }
  }
  ~GdalSource() override {
    warped_.reset();  // the warped VRT holds a reference to the source: close it first
    source_.reset();
  }

  std::string_view formatName() const override { return driver_; }

 private:
  Result<void> readSourceColumns(int64_t row, int64_t sourceColumn, int64_t count,
                                 int16_t* out) const override {
    std::vector<double> values(static_cast<size_t>(count));
    const int64_t datasetRow = flipRows_ ? rows_ - 1 - row : row;
    {
      QuietGdal quiet;
      std::lock_guard lock(mutex_);  // GDAL datasets are not thread-safe
      if (GDALRasterIO(band_, GF_Read, static_cast<int>(sourceColumn), static_cast<int>(datasetRow),
                       static_cast<int>(count), 1, values.data(), static_cast<int>(count), 1,
                       GDT_Float64, 0, 0) != CE_None) {
        return makeError(path() + ": reading row " + std::to_string(datasetRow) +
                         " failed: " + QuietGdal::message());
      }
    }
    const formats::VerticalUnits& units = verticalUnits();
    for (int64_t i = 0; i < count; ++i) {
      const double v = values[static_cast<size_t>(i)];
      // No-data is the stored value, before scale and offset.
      const double meters = units.toMeters(v);
      if (!std::isfinite(v) || (hasNoData_ && v == noData_) || !std::isfinite(meters)) {
        out[i] = kNoDataHeight;
      } else {
        // Ties to even, as numpy's round: ETOPO20.DEM was made from etopo20.cdf that way.
        out[i] = static_cast<int16_t>(std::clamp(std::nearbyint(meters), -32768.0, 32767.0));
      }
    }
    return {};
  }

  DatasetPtr source_, warped_;
  std::string driver_;
  int64_t rows_;
  bool flipRows_;
  GDALRasterBandH band_ = nullptr;
  double noData_ = 0;
  int hasNoData_ = 0;
  mutable std::mutex mutex_;
};

// The band's unit type, scale and offset (the warped VRT does not carry them: read the source's).
Result<formats::VerticalUnits> bandVerticalUnits(GDALDatasetH source, const std::string& path,
                                                 const formats::VerticalOverride& zOverride) {
  GDALRasterBandH band = GDALGetRasterBand(source, 1);
  const char* unit = GDALGetRasterUnitType(band);
  int hasScale = 0, hasOffset = 0;
  const double scale = GDALGetRasterScale(band, &hasScale);
  const double offset = GDALGetRasterOffset(band, &hasOffset);
  return formats::resolveVerticalUnits(path, unit ? unit : "", hasScale ? scale : 1.0,
                                       hasOffset ? offset : 0.0, zOverride);
}

// What makes `dataset` a picture rather than heights ("" when nothing does): 8-bit bands that
// GDAL calls red, green and blue, or a palette.
std::string pictureBands(GDALDatasetH dataset) {
  GDALRasterBandH first = GDALGetRasterBand(dataset, 1);
  if (GDALGetRasterColorInterpretation(first) == GCI_PaletteIndex) return "a paletted image";
  if (GDALGetRasterDataType(first) != GDT_Byte || GDALGetRasterCount(dataset) < 3) return "";
  struct Colour {
    GDALColorInterp interpretation;
    const char* name;
  };
  static constexpr Colour kColours[] = {
      {GCI_RedBand, "red"}, {GCI_GreenBand, "green"}, {GCI_BlueBand, "blue"}};
  std::string named;
  for (int b = 1; b <= 3; ++b) {
    const Colour& c = kColours[b - 1];
    if (GDALGetRasterColorInterpretation(GDALGetRasterBand(dataset, b)) != c.interpretation) {
      return "";
    }
    named += (named.empty() ? "" : ", ") + std::to_string(b) + " " + c.name;
  }
  return "an 8-bit colour image (bands " + named + ")";
}

}  // namespace

Result<std::unique_ptr<RasterSource>> openGdalSource(const std::filesystem::path& path,
                                                     const RasterOpenOptions& options) {
  registerGdalOnce();
  QuietGdal quiet;
  const std::string name = path.string();
  DatasetPtr source(GDALOpenEx(name.c_str(),
                               GDAL_OF_RASTER | GDAL_OF_READONLY | GDAL_OF_VERBOSE_ERROR, nullptr,
                               nullptr, nullptr));
  if (!source) return makeError(name + ": GDAL cannot open it as a raster: " + quiet.message());
  if (GDALGetRasterCount(source.get()) < 1) return makeError(name + ": has no raster band");
  if (const std::string picture = pictureBands(source.get());
      !picture.empty() && !options.allowImages) {
    return makeError(name + ": " + picture + ", not elevation: tile it as a layer with " +
                     "`globe-tiler imagery`, or give --force to tile its band 1 as heights");
  }
  const std::string driver = GDALGetDriverShortName(GDALGetDatasetDriver(source.get()));
  auto vertical = bandVerticalUnits(source.get(), name, options.vertical);
  if (!vertical) return Error{vertical.error()};

  double gt[6];
  if (GDALGetGeoTransform(source.get(), gt) != CE_None) {
    return makeError(name + ": has no geotransform (" + driver + " raster not georeferenced)");
  }
  if (gt[2] != 0 || gt[4] != 0)
    return makeError(name + ": rotated geotransforms are not supported");

  OGRSpatialReferenceH srs = GDALGetSpatialRef(source.get());
  DatasetPtr warped;
  if (srs ? !isDegrees(srs)
          : !plausiblyDegrees(gt, GDALGetRasterXSize(source.get()),
                              GDALGetRasterYSize(source.get()))) {
    if (!srs) {
      return makeError(name + ": has no coordinate system and its geotransform is not in degrees");
    }
    auto w = warpToWgs84(source.get(), name);
    if (!w) return Error{w.error()};
    warped = std::move(*w);
    if (GDALGetGeoTransform(warped.get(), gt) != CE_None) {
      return makeError(name + ": warped raster has no geotransform");
    }
  }

  GDALDatasetH ds = warped ? warped.get() : source.get();
  const int cols = GDALGetRasterXSize(ds), rows = GDALGetRasterYSize(ds);
  if (cols < 1 || rows < 1) return makeError(name + ": raster is empty");
  if (!(gt[1] > 0) || gt[5] == 0 || !std::isfinite(gt[0]) || !std::isfinite(gt[3]) ||
      !std::isfinite(gt[1]) || !std::isfinite(gt[5])) {
    return makeError(name + ": unsupported geotransform (columns must run eastwards)");
  }
  // The geotransform gives the corner of pixel (0, 0); grids use sample centres, north first.
  const bool flipRows = gt[5] > 0;
  geo::SampleGrid grid;
  grid.cols = cols;
  grid.rows = rows;
  grid.columnStepDegrees = gt[1];
  grid.rowStepDegrees = std::abs(gt[5]);
  grid.firstColumnLongitudeDegrees = gt[0] + gt[1] / 2;
  grid.firstRowLatitudeDegrees = flipRows ? gt[3] + (rows - 0.5) * gt[5] : gt[3] + gt[5] / 2;
  return std::unique_ptr<RasterSource>(std::make_unique<GdalSource>(
      name, grid, std::move(source), std::move(warped), flipRows, driver, std::move(*vertical)));
}

}  // namespace globe::rasters
