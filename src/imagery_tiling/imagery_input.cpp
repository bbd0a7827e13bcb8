#include "imagery_tiling/imagery_input.hpp"

#include <cpl_conv.h>
#include <gdal.h>
#include <gdal_alg.h>
#include <ogr_srs_api.h>
#include <tinyxml2.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "geo/tile_id.hpp"
#include "imagery_tiling/gdal_dataset.hpp"
#include "imagery_tiling/imagery_bands.hpp"

namespace globe::imagery_tiling {
namespace {

namespace fs = std::filesystem;

constexpr const char* kTmsFileName = "tilemapresource.xml";

std::string lastGdalError() {
  const char* message = CPLGetLastErrorMsg();
  return message != nullptr && *message != '\0' ? message : "no driver recognises it";
}

formats::BoundsDegrees clampToGlobe(formats::BoundsDegrees b) {
  return {std::max(b.west, -180.0), std::max(b.south, -90.0), std::min(b.east, 180.0),
          std::min(b.north, 90.0)};
}

// Splits a footprint that crosses ±180° into the part on the globe and the part beyond.
void setFootprint(ImageryInput& input, formats::BoundsDegrees raw) {
  if (raw.east - raw.west > 360) raw.east = raw.west + 360;
  input.extent = clampToGlobe(raw);
  if (raw.east > 180) {
    input.wrappedExtent = clampToGlobe({raw.west - 360, raw.south, raw.east - 360, raw.north});
    input.wrapShiftDegrees = 360;
  } else if (raw.west < -180) {
    input.wrappedExtent = clampToGlobe({raw.west + 360, raw.south, raw.east + 360, raw.north});
    input.wrapShiftDegrees = -360;
  }
}

std::string crsName(OGRSpatialReferenceH srs) {
  if (srs == nullptr) return "EPSG:4326 (assumed)";
  const char* authority = OSRGetAuthorityName(srs, nullptr);
  const char* code = OSRGetAuthorityCode(srs, nullptr);
  if (authority != nullptr && code != nullptr) return std::string(authority) + ":" + code;
  char* wkt = nullptr;
  OSRExportToWkt(srs, &wkt);
  std::string text = wkt != nullptr ? wkt : "";
  CPLFree(wkt);
  return text.size() > 80 ? text.substr(0, 80) + "..." : text;
}

std::string wgs84Wkt() {
  OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
  OSRImportFromEPSG(srs, 4326);
  char* wkt = nullptr;
  OSRExportToWkt(srs, &wkt);
  std::string text = wkt != nullptr ? wkt : "";
  CPLFree(wkt);
  OSRDestroySpatialReference(srs);
  return text;
}

Result<ImageryInput> describeRaster(const std::string& argument,
                                    const ImageryInputOptions& options) {
  ImageryInput input;
  input.argument = argument;
  GdalDataset dataset(
      GDALOpenEx(argument.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
  if (!dataset) {
    std::error_code error;
    if (!fs::exists(argument, error)) return makeError(argument + ": no such file");
    return makeError(argument + ": not a raster GDAL can open: " + lastGdalError());
  }
  GDALDatasetH ds = dataset.get();
  const int columns = GDALGetRasterXSize(ds), rows = GDALGetRasterYSize(ds);
  input.info.path = argument;
  input.info.driver = GDALGetDriverShortName(GDALGetDatasetDriver(ds));
  input.info.columns = columns;
  input.info.rows = rows;
  if (auto bands = chooseImageryBands(ds, argument, options, input); !bands) {
    return Error{bands.error()};
  }

  double geo[6];
  const bool hasGeoTransform = GDALGetGeoTransform(ds, geo) == CE_None;
  const bool hasGcps = GDALGetGCPCount(ds) > 0;
  const bool hasRpc = GDALGetMetadata(ds, "RPC") != nullptr;
  OGRSpatialReferenceH srs = GDALGetSpatialRef(ds);
  if (!hasGeoTransform && !hasGcps && !hasRpc) {
    if (!options.bounds) {
      return makeError(argument +
                       ": has no georeference (no geotransform, world file, GCPs or RPCs): give "
                       "--bounds W,S,E,N for an image in plain longitude/latitude");
    }
    const formats::BoundsDegrees& b = *options.bounds;
    input.assignedGeoTransform = std::array<double, 6>{
        b.west, (b.east - b.west) / columns, 0, b.north, 0, -(b.north - b.south) / rows};
    setFootprint(input, b);
    input.pixelDegrees = std::min((b.east - b.west) / columns, (b.north - b.south) / rows);
    input.info.crs = "EPSG:4326 (--bounds)";
  } else {
    if (srs == nullptr && !hasRpc) {
      // A world file carries no CRS: accept it as longitude/latitude when it fits the globe.
      const double east = geo[0] + geo[1] * columns, south = geo[3] + geo[5] * rows;
      if (!hasGeoTransform || geo[2] != 0 || geo[4] != 0 || geo[0] < -180.001 || east > 180.001 ||
          geo[3] > 90.001 || south < -90.001) {
        return makeError(argument +
                         ": has a georeference but no coordinate reference system (add a .prj or "
                         "use gdal_translate -a_srs)");
      }
      input.assumedSrsWkt = wgs84Wkt();
    }
    input.info.crs = crsName(srs);
    const std::string dst = "DST_SRS=" + wgs84Wkt();
    const std::string src = "SRC_SRS=" + input.assumedSrsWkt;
    const char* transformerOptions[] = {
        dst.c_str(), input.assumedSrsWkt.empty() ? nullptr : src.c_str(), nullptr};
    void* transformer =
        GDALCreateGenImgProjTransformer2(ds, nullptr, const_cast<char**>(transformerOptions));
    if (transformer == nullptr) {
      return makeError(argument + ": cannot transform to longitude/latitude: " + lastGdalError());
    }
    double outGeo[6];
    double extent[4];
    int outColumns = 0, outRows = 0;
    const CPLErr suggested = GDALSuggestedWarpOutput2(ds, GDALGenImgProjTransform, transformer,
                                                      outGeo, &outColumns, &outRows, extent, 0);
    GDALDestroyGenImgProjTransformer(transformer);
    if (suggested != CE_None) {
      return makeError(argument +
                       ": cannot find its footprint in longitude/latitude: " + lastGdalError());
    }
    setFootprint(input, {extent[0], extent[1], extent[2], extent[3]});
    input.pixelDegrees = outGeo[1];
  }
  if (!(input.pixelDegrees > 0) || input.extent.west >= input.extent.east ||
      input.extent.south >= input.extent.north) {
    return makeError(argument + ": its footprint in longitude/latitude is empty or off the globe");
  }
  return input;
}

Result<ImageryInput> describeTms(const std::string& argument) {
  const fs::path xmlPath = fs::path(argument) / kTmsFileName;
  tinyxml2::XMLDocument document;
  if (document.LoadFile(xmlPath.c_str()) != tinyxml2::XML_SUCCESS) {
    return makeError(xmlPath.string() + ": cannot read: " + document.ErrorStr());
  }
  auto fail = [&](const std::string& what) {
    return makeError(xmlPath.string() + ": " + what +
                     " (a geodetic TMS of 256-pixel tiles in "
                     "EPSG:4326 is needed)");
  };
  const tinyxml2::XMLElement* map = document.FirstChildElement("TileMap");
  if (map == nullptr) return fail("no <TileMap>");
  const tinyxml2::XMLElement* srs = map->FirstChildElement("SRS");
  const tinyxml2::XMLElement* format = map->FirstChildElement("TileFormat");
  const tinyxml2::XMLElement* sets = map->FirstChildElement("TileSets");
  const tinyxml2::XMLElement* origin = map->FirstChildElement("Origin");
  const tinyxml2::XMLElement* box = map->FirstChildElement("BoundingBox");
  if (srs == nullptr || srs->GetText() == nullptr || std::string(srs->GetText()) != "EPSG:4326") {
    return fail("SRS is not EPSG:4326");
  }
  if (format == nullptr || format->IntAttribute("width") != 256 ||
      format->IntAttribute("height") != 256 || format->Attribute("extension") == nullptr) {
    return fail("TileFormat is not 256x256 with an extension");
  }
  if (sets == nullptr || sets->Attribute("profile") == nullptr ||
      std::string(sets->Attribute("profile")) != "geodetic") {
    return fail("TileSets profile is not geodetic");
  }
  if (origin == nullptr || origin->DoubleAttribute("x") != -180 ||
      origin->DoubleAttribute("y") != -90) {
    return fail("Origin is not (-180, -90)");
  }
  ImageryInput input;
  input.kind = ImageryInput::Kind::Tms;
  input.argument = argument;
  input.tmsExtension = format->Attribute("extension");
  int maxOrder = -1;
  for (const auto* set = sets->FirstChildElement("TileSet"); set != nullptr;
       set = set->NextSiblingElement("TileSet")) {
    const int order = set->IntAttribute("order", -1);
    const char* href = set->Attribute("href");
    if (order < 0 || order > static_cast<int>(geo::kMaxLevel) || href == nullptr ||
        std::string(href) != std::to_string(order)) {
      return fail("a TileSet whose order/href is not a level number");
    }
    maxOrder = std::max(maxOrder, order);
  }
  if (maxOrder < 0) return fail("no TileSet");
  input.tmsMaxLevel = static_cast<uint32_t>(maxOrder);
  input.extent = box == nullptr
                     ? formats::BoundsDegrees{-180, -90, 180, 90}
                     : clampToGlobe({box->DoubleAttribute("minx"), box->DoubleAttribute("miny"),
                                     box->DoubleAttribute("maxx"), box->DoubleAttribute("maxy")});
  input.pixelDegrees = 180.0 / 256 / std::ldexp(1.0, maxOrder);
  input.info.path = argument;
  input.info.driver = "TMS";
  input.info.columns = int64_t{512} << maxOrder;
  input.info.rows = int64_t{256} << maxOrder;
  input.info.crs = "EPSG:4326";
  input.info.bands = std::string("tiles as is (") + input.tmsExtension + ")";
  return input;
}

}  // namespace

bool overlapsFootprint(const ImageryInput& input, double westDegrees, double southDegrees,
                       double eastDegrees, double northDegrees) {
  auto overlaps = [&](const formats::BoundsDegrees& e) {
    return westDegrees < e.east && eastDegrees > e.west && southDegrees < e.north &&
           northDegrees > e.south;
  };
  return overlaps(input.extent) || (input.wrappedExtent && overlaps(*input.wrappedExtent));
}

uint32_t imageryFinestLevel(double pixelDegrees) {
  uint32_t level = 0;
  // 1e-9 relative: a source whose pixel is exactly a level's texel (a TMS tree) lands on it.
  while (level < geo::kMaxLevel &&
         180.0 / 256 / std::ldexp(1.0, static_cast<int>(level)) > pixelDegrees * (1 + 1e-9)) {
    ++level;
  }
  return level;
}

Result<std::vector<ImageryInput>> describeImageryInputs(const std::vector<std::string>& arguments,
                                                        const ImageryInputOptions& options) {
  GDALAllRegister();
  std::vector<ImageryInput> inputs;
  uint32_t deepest = 0;
  for (size_t i = 0; i < arguments.size(); ++i) {
    std::error_code error;
    const bool tms = fs::is_directory(arguments[i], error) &&
                     fs::exists(fs::path(arguments[i]) / kTmsFileName, error);
    auto input = tms ? describeTms(arguments[i]) : describeRaster(arguments[i], options);
    if (!input) return Error{input.error()};
    input->order = i;
    input->naturalLevel = tms ? input->tmsMaxLevel : imageryFinestLevel(input->pixelDegrees);
    deepest = std::max(deepest, input->naturalLevel);
    inputs.push_back(std::move(*input));
  }
  // --bounds serves the inputs without georeference; given where none lacks it, it would be
  // silently ignored.
  if (options.bounds && std::none_of(inputs.begin(), inputs.end(), [](const ImageryInput& input) {
        return input.assignedGeoTransform.has_value();
      })) {
    std::string names;
    for (const ImageryInput& input : inputs) names += (names.empty() ? "" : ", ") + input.argument;
    return makeError(names + (inputs.size() == 1 ? " is" : " are") +
                     " georeferenced; --bounds is only for images without georeferencing");
  }
  for (ImageryInput& input : inputs) {
    input.finestLevel = input.naturalLevel;
    // --max-level: the finest inputs go exactly that deep, none deeper.
    if (options.maxLevel) {
      input.finestLevel = input.naturalLevel >= deepest
                              ? *options.maxLevel
                              : std::min(input.naturalLevel, *options.maxLevel);
    }
    input.info.pixelDegrees = input.pixelDegrees;
    input.info.bounds = input.extent;
    input.info.finestLevel = input.finestLevel;
  }
  return inputs;
}

}  // namespace globe::imagery_tiling
